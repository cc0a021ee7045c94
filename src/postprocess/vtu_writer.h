#pragma once

#include <fem/elastic_model.h>
#include <fem/fe_space.h>

#include <deal.II/lac/trilinos_vector.h>

#include <string>
#include <utility>
#include <vector>

namespace FloorBlock::Postprocess
{
  /** Cell fields of a VTU file by name, one value per active cell. */
  using CellFields = std::vector<std::pair<std::string, std::vector<double>>>;

  /**
   * @brief Writes one increment as `<directory>/solution-NNNN.vtu` and
   * rewrites `<directory>/solution.pvd` listing all increments so far.
   *
   * Fields: displacement (m), stress components incl. the plane-strain
   * out-of-plane stress (Pa), von Mises stress (Pa), in-plane principal
   * stresses (Pa) (3D: the six stress components and von Mises), material
   * id, and a nodal debug field contact_state (-1 no contact node, 0
   * open, 1 stick, 2 slip).
   *
   * @param[in] space FE space.
   * @param[in] model Elastic laws per material id.
   * @param[in] solution Displacement (m).
   * @param[in] state_dofs x-DoF of each contact node.
   * @param[in] states State value of each contact node.
   * @param[in] directory Output folder (created if missing).
   * @param[in,out] records (index, file name) of the increments written.
   * @param[in] cell_fields Further cell fields (e.g. strength_factor).
   */
  template <int dim>
  void
  write_vtu_increment(
    const Fem::FeSpace<dim>                            &space,
    const Fem::ElasticModel<dim>                       &model,
    const dealii::TrilinosWrappers::MPI::Vector        &solution,
    const std::vector<dealii::types::global_dof_index> &state_dofs,
    const std::vector<double>                          &states,
    const std::string                                  &directory,
    std::vector<std::pair<double, std::string>>        &records,
    const CellFields                                   &cell_fields = {});
} // namespace FloorBlock::Postprocess
