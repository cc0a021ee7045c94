#pragma once

#include <fem/fe_space.h>
#include <solver/near_null_space.h>

namespace FloorBlock::Fem
{
  /**
   * @brief The rigid-body modes of a vector-valued displacement space, the
   * near-null space of elasticity for ML AMG.
   *
   * Translations along each axis, then the small rotations
   * \f$\omega \times x\f$ about each axis through the origin (2D: about z
   * only), evaluated at every locally owned unknown's support point. With
   * the translations alone (DoFTools::extract_constant_modes) ML's coarse
   * spaces cannot rotate an aggregate, and the bending of the slender
   * blocks and the rocking of a block on a small contact fall to GMRES:
   * on the 3D plane-strain scene refined from 10.5k to 471k DoFs the first
   * twelve solves to 1e-8 took 45-129 and 49-141 GMRES iterations with
   * translations and a V-cycle, and 31-105 at 471k DoFs with these modes
   * and a W-cycle.
   *
   * @param[in] space FE space of dim components (FE_Q^dim).
   * @return dim (dim + 1) / 2 modes over the locally owned unknowns,
   *   n_components = dim.
   */
  template <int dim>
  Solver::NearNullSpace
  rigid_body_modes(const FeSpace<dim> &space);
} // namespace FloorBlock::Fem
