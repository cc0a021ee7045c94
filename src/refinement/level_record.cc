#include <refinement/level_record.h>

namespace FloorBlock::Refinement
{
  std::vector<Quantity>
  quantities_of_interest(const unsigned int n_blocks)
  {
    std::vector<Quantity> quantities;
    for (unsigned int joint = 1; joint <= n_blocks; ++joint)
      quantities.push_back({joint == n_blocks ? std::string("Q_face") :
                                                "Q_" + std::to_string(joint),
                            "N_per_m",
                            [joint](const LevelRecord &record) {
                              return record.joint_normal_forces.at(joint - 1);
                            }});
    quantities.push_back(
      {"contact_length_face", "m", [](const LevelRecord &record) {
         return record.face_contact_length;
       }});
    quantities.push_back(
      {"sigma_max_face", "Pa", [](const LevelRecord &record) {
         return record.face_sigma_max;
       }});
    quantities.push_back(
      {"sigma_max_averaged_face", "Pa", [](const LevelRecord &record) {
         return record.face_sigma_max_averaged;
       }});
    return quantities;
  }

  std::vector<std::optional<double>>
  quantity_series(const std::vector<LevelRecord> &levels,
                  const Quantity                 &quantity)
  {
    std::vector<std::optional<double>> series;
    for (const LevelRecord &record : levels)
      series.push_back(record.converged() ?
                         std::optional<double>(quantity.value(record)) :
                         std::nullopt);
    return series;
  }
} // namespace FloorBlock::Refinement
