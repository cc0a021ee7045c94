#pragma once

#include <contact/contact_problem.h>
#include <material/elastic_law.h>

namespace FloorBlock::Verification
{
  /** Rock of the chapter's Table 6.1: K = 9 GPa, G = 6.7 GPa. */
  inline Material::ElasticLaw<2>
  table_rock()
  {
    return Material::ElasticLaw<2>::from_bulk_shear(9e9, 6.7e9);
  }

  /**
   * Direct solver and a tight Newton tolerance (1e-12 relative), so the
   * verification cases can check equilibrium quantities to 1e-8.
   */
  inline Contact::ContactSolverSettings
  verification_settings(const unsigned int fe_degree = 1)
  {
    Contact::ContactSolverSettings settings;
    settings.fe_degree                 = fe_degree;
    settings.linear.kind               = Solver::LinearSolverKind::direct;
    settings.newton.relative_tolerance = 1e-12;
    settings.max_cutbacks              = 3;
    return settings;
  }

  /**
   * Relative tolerance of an equilibrium quantity that the discretisation
   * represents exactly (a resultant force, a uniform traction): what
   * remains under verification_settings() is the direct solver's round-off
   * (condition number about 1e6 x 1e-16) and the Newton tolerance 1e-12,
   * so 1e-8 is a safe bound.
   */
  constexpr double equilibrium_tolerance = 1e-8;

  /** Support fixing the x and/or y displacement of a boundary. */
  inline Contact::SupportDefinition<2>
  fixed_support(const dealii::types::boundary_id id,
                const bool                       fix_x,
                const bool                       fix_y)
  {
    Contact::SupportDefinition<2> support;
    support.boundary_id            = id;
    support.constrained_components = {{fix_x, fix_y}};
    return support;
  }
} // namespace FloorBlock::Verification
