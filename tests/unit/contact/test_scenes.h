#pragma once

#include <contact/scene.h>
#include <material/elastic_law.h>

namespace FloorBlock
{
  namespace Testing
  {
    /** Rock of the chapter's Table 6.1: K = 9 GPa, G = 6.7 GPa. */
    inline Material::ElasticLaw<2>
    table_rock()
    {
      return Material::ElasticLaw<2>::from_bulk_shear(9e9, 6.7e9);
    }

    /** Direct solver, tight Newton tolerance: tests check equilibrium to 1e-8. */
    inline Contact::ContactSolverSettings
    test_settings(const unsigned int degree = 1)
    {
      Contact::ContactSolverSettings settings;
      settings.fe_degree                  = degree;
      settings.linear.kind                = Solver::LinearSolverKind::direct;
      settings.newton.relative_tolerance  = 1e-12;
      settings.max_cutbacks               = 3;
      settings.rigid_constraint_tolerance = 1e-8;
      return settings;
    }

    inline Contact::SupportDefinition<2>
    fixed_support(const dealii::types::boundary_id id, const bool x, const bool y)
    {
      Contact::SupportDefinition<2> support;
      support.boundary_id            = id;
      support.constrained_components = {{x, y}};
      return support;
    }
  } // namespace Testing
} // namespace FloorBlock
