#include <fem/cell_stress.h>
#include <output/deformed_picture.h>
#include <pipeline/deformed_view.h>

namespace FloorBlock::Pipeline
{
  void
  write_deformed_view(const Contact::ContactSolver<2> &solver,
                      const Fem::ElasticModel<2>      &model,
                      const std::string               &png_path)
  {
    const auto &nodes     = solver.contact_nodes();
    const auto  responses = solver.responses_at_solution();
    if (responses.size() != nodes.size())
      return; // nothing converged: no state to draw
    std::vector<Output::PictureMarker> markers;
    markers.reserve(nodes.size());
    for (unsigned int p = 0; p < nodes.size(); ++p)
      markers.push_back(
        {nodes[p].position, Contact::state_name(responses[p].state)});
    Output::write_deformed_picture(solver.space().dof_handler(),
                                   solver.solution(),
                                   Fem::cell_major_compressive_stress(
                                     solver.space(), model, solver.solution()),
                                   markers,
                                   png_path,
                                   0.,
                                   "joint node states");
  }
} // namespace FloorBlock::Pipeline
