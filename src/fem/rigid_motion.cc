#include <fem/rigid_motion.h>

#include <vector>

namespace FloorBlock
{
  namespace Fem
  {
    std::map<dealii::types::material_id, RigidMotion<2>>
    fit_rigid_motions(const FeSpace<2>                            &space,
                      const dealii::TrilinosWrappers::MPI::Vector &solution)
    {
      constexpr int dim = 2;
      struct Sample
      {
        dealii::Point<dim>     position;
        dealii::Tensor<1, dim> displacement;
      };
      std::map<dealii::types::material_id, std::vector<Sample>> samples;
      for (const auto &cell : space.dof_handler().active_cell_iterators())
        for (const unsigned int v : cell->vertex_indices())
          {
            Sample sample{cell->vertex(v), {}};
            for (unsigned int c = 0; c < dim; ++c)
              sample.displacement[c] = solution(cell->vertex_dof_index(v, c));
            samples[cell->material_id()].push_back(sample);
          }
      std::map<dealii::types::material_id, RigidMotion<dim>> motions;
      for (const auto &[material, body] : samples)
        {
          dealii::Point<dim>     centroid;
          dealii::Tensor<1, dim> mean_displacement;
          for (const auto &sample : body)
            {
              centroid += sample.position / double(body.size());
              mean_displacement += sample.displacement / double(body.size());
            }
          double moment = 0., inertia = 0.;
          for (const auto &sample : body)
            {
              const dealii::Tensor<1, dim> arm = sample.position - centroid;
              moment += arm[0] * sample.displacement[1] -
                        arm[1] * sample.displacement[0];
              inertia += arm.norm_square();
            }
          RigidMotion<dim> motion;
          motion.translation = mean_displacement;
          motion.rotation    = inertia > 0. ? moment / inertia : 0.;
          motions[material]  = motion;
        }
      return motions;
    }
  } // namespace Fem
} // namespace FloorBlock
