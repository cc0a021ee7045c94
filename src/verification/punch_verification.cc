#include <analytic/asymptotic_fit.h>
#include <contact/contact_solver.h>
#include <material/elastic_law.h>
#include <verification/block_assembly_mesh.h>
#include <verification/punch_verification.h>
#include <verification/verification_setup.h>

#include <deal.II/grid/tria.h>

#include <postprocess/increment_post_processor.h>
#include <refinement/matched_refinement.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace FloorBlock::Verification
{
  // The model's ids and sizes: a named namespace, as the verification models
  // share names (block, base, ...) within one unity batch.
  namespace PunchModel
  {
    constexpr dealii::types::material_id block = 1, base = 2;
    constexpr dealii::types::boundary_id block_axis = 11, block_side = 12,
                                         block_bottom = 13, block_top = 14;
    constexpr dealii::types::boundary_id base_axis = 21, base_side = 22,
                                         base_bottom = 23, base_contact = 24,
                                         base_free_top = 25;
    constexpr double half_width   = 1.;   // m, the block's half-width
    constexpr double block_height = 2.;   // m
    constexpr double base_size    = 3.;   // m, width and depth of the base
    constexpr double cell_size    = 0.25; // m, before refinement
    constexpr double stuck_friction_coefficient = 10.;
    constexpr double pi                         = 3.14159265358979323846;

    /**
     * Square cells of 0.25 m on both bodies, aligned at the interface, then
     * corner_refinements halvings of the cells within two cell diameters of
     * the corner, both sides of the interface kept matched
     * (Refinement::prepare_matched_refinement()).
     */
    void
    make_punch_mesh(const unsigned int        corner_refinements,
                    dealii::Triangulation<2> &mesh)
    {
      const auto cells = [](const double length) {
        return static_cast<unsigned int>(std::lround(length / cell_size));
      };
      BlockSpec upper{0.,
                      half_width,
                      0.,
                      block_height,
                      cells(half_width),
                      cells(block_height),
                      block,
                      block_axis,
                      block_side,
                      block_bottom,
                      block_top};
      BlockSpec lower{0.,
                      base_size,
                      -base_size,
                      0.,
                      cells(base_size),
                      cells(base_size),
                      base,
                      base_axis,
                      base_side,
                      base_bottom,
                      base_contact};
      lower.split_x   = half_width;
      lower.top_right = base_free_top;
      make_block_assembly({upper, lower}, mesh);
      const dealii::Point<2> corner(half_width, 0.);
      for (unsigned int level = 0; level < corner_refinements; ++level)
        {
          for (const auto &cell : mesh.active_cell_iterators())
            if (cell->center().distance(corner) < 2. * cell->diameter())
              cell->set_refine_flag();
          Refinement::prepare_matched_refinement(
            mesh, {{base_contact, block_bottom}});
          mesh.execute_coarsening_and_refinement();
        }
    }

    double
    smallest_cell(const dealii::Triangulation<2> &mesh)
    {
      double smallest = 1e300;
      for (const auto &cell : mesh.active_cell_iterators())
        smallest = std::min(smallest, cell->diameter() / std::sqrt(2.));
      return smallest;
    }
  } // namespace PunchModel

  PunchCase
  run_punch_case(const PunchSettings           &settings,
                 const Analytic::InterfaceState state)
  {
    using namespace PunchModel;
    PunchCase result;
    result.state = state;

    Analytic::WedgePair corner;
    corner.first_angle  = pi / 2.;
    corner.second_angle = pi;
    const double shear_modulus =
      settings.youngs_modulus / (2. * (1. + settings.poissons_ratio));
    corner.first_material  = {shear_modulus, settings.poissons_ratio};
    corner.second_material = corner.first_material;
    corner.state           = state;
    const std::vector<Analytic::CornerMode> modes =
      Analytic::corner_modes(corner);
    result.theory_exponent        = modes.at(0).exponent.real();
    result.second_theory_exponent = modes.at(1).exponent.real();

    dealii::Triangulation<2> mesh;
    make_punch_mesh(settings.corner_refinements, mesh);
    result.smallest_cell = smallest_cell(mesh);

    Contact::ContactProblem<2> scene;
    const auto                 law =
      Material::ElasticLaw<2>::from_youngs_poisson(settings.youngs_modulus,
                                                   settings.poissons_ratio);
    scene.model.laws.emplace(block, law);
    scene.model.laws.emplace(base, law);
    scene.model.pressures[block_top] = settings.pressure;
    scene.supports                   = {fixed_support(block_axis, true, false),
                                        fixed_support(base_axis, true, false),
                                        fixed_support(base_bottom, true, true)};
    Contact::JointDefinition<2> interface;
    interface.name   = "punch";
    interface.side_a = base_contact;
    interface.side_b = block_bottom;
    interface.law    = Contact::JointLawKind::rigid;
    interface.parameters.friction_angle =
      state == Analytic::InterfaceState::stuck ?
        std::atan(stuck_friction_coefficient) :
        0.;
    scene.joints = {interface};
    scene.steps  = {0, 1, 0};

    const Contact::ContactSolverSettings numerics = verification_settings();
    Contact::ContactSolver<2>            solver(mesh, scene, numerics);
    const Contact::SolveResult           solved =
      Postprocess::solve_with_reports(solver, numerics);
    result.n_dofs = solved.n_dofs;

    // Interface pressure against the distance r of its node from the
    // corner, over the fit range.
    std::vector<Analytic::RadialSample> samples;
    result.fit_from = punch_fit_from_cells * result.smallest_cell;
    result.fit_to   = punch_fit_to;
    for (const auto &sample : solved.increments.back().joints.at(0).profile)
      {
        const double r = half_width - sample.position[0];
        if (r >= result.fit_from && r <= result.fit_to)
          samples.push_back({r, sample.normal_traction});
      }
    const Analytic::AsymptoticFit one_term = Analytic::one_term_fit(samples);
    const Analytic::AsymptoticFit two_terms =
      Analytic::two_term_fit(samples, result.second_theory_exponent);
    result.n_fit_points      = two_terms.n_samples;
    result.one_term_exponent = one_term.lambda1;
    result.fitted_exponent   = two_terms.lambda1;
    result.fit_residual      = two_terms.rms_relative_residual;
    result.second_over_first =
      two_terms.k1 != 0. ? two_terms.k2 / two_terms.k1 : 0.;
    result.one_term_validity =
      Analytic::one_term_validity_distance(two_terms, 0.1);
    return result;
  }
} // namespace FloorBlock::Verification
