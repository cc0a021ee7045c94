#include <compare/joint_name.h>
#include <compare/joint_states.h>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>

namespace FloorBlock::Compare
{
  namespace
  {
    double
    friction_use(const Contact::JointReport &joint, const double angle)
    {
      if (!(joint.normal_force > 0.))
        return 0.;
      return std::abs(joint.shear_force) /
             (joint.normal_force * std::tan(angle));
    }

    bool
    all_at_limit(const std::vector<double> &uses, const std::size_t count)
    {
      return std::all_of(uses.begin(),
                         uses.begin() + count,
                         [](const double use) {
                           return use >= at_friction_limit;
                         });
    }

    std::string
    range_text(const std::vector<double> &uses)
    {
      const auto [low, high] = std::minmax_element(uses.begin(), uses.end());
      const std::string low_text  = fmt::format("{:.3g}", *low);
      const std::string high_text = fmt::format("{:.3g}", *high);
      return low_text == high_text ? low_text : low_text + " to " + high_text;
    }
  } // namespace

  JointStates
  joint_states(const Contact::IncrementResult &increment,
               const Scene::ClosedForms       &closed_forms)
  {
    const Analytic::BlockChain &chain = closed_forms.chain;
    const unsigned int          n     = chain.n_blocks();
    JointStates                 states;
    states.vertical_use.assign(n, 0.);
    states.bedding_use.assign(n, 0.);
    std::vector<bool> bed_open(n, true);
    for (const Contact::JointReport &report : increment.joints)
      {
        const JointName name = parse_joint_name(report.name);
        if (name.number == 0 || name.number > n)
          continue;
        if (name.kind == "vertical")
          states.vertical_use[name.number - 1] =
            friction_use(report, chain.vertical_friction);
        else if (name.kind == "bedding")
          {
            states.bedding_use[name.number - 1] =
              friction_use(report, chain.bedding_friction);
            bed_open[name.number - 1] = !(report.normal_force > 0.);
          }
      }
    for (unsigned int i = 0; i < n; ++i)
      if (bed_open[i])
        states.open_beds.push_back(i + 1);
    for (unsigned int j = 1; j <= n; ++j)
      states.slip_chain_holds.push_back(all_at_limit(states.vertical_use, j) &&
                                        all_at_limit(states.bedding_use, j));

    const bool beds_slip      = all_at_limit(states.bedding_use, n);
    const bool verticals_slip = all_at_limit(states.vertical_use, n);
    const bool verticals_stick =
      std::all_of(states.vertical_use.begin(),
                  states.vertical_use.end(),
                  [](const double use) { return use < at_friction_limit; });
    if (beds_slip && verticals_slip)
      states.holding = {Scene::Mechanism::no_rotation,
                        Scene::Mechanism::rotation_vertical_slip};
    else if (beds_slip && verticals_stick)
      states.holding = {Scene::Mechanism::rotation_no_vertical_slip};

    states.text =
      fmt::format("vertical joints at {} of their friction limit, beds at {}{}",
                  range_text(states.vertical_use),
                  range_text(states.bedding_use),
                  states.open_beds.empty() ?
                    std::string() :
                    fmt::format(" (bed{} {} open)",
                                states.open_beds.size() > 1 ? "s" : "",
                                fmt::join(states.open_beds, ", ")));
    return states;
  }
} // namespace FloorBlock::Compare
