#include <analytic/hertz.h>
#include <common/input_error.h>
#include <contact/contact_solver.h>
#include <fem/point_stress.h>
#include <verification/hertz_verification.h>

#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>

#include <postprocess/increment_post_processor.h>

#include <algorithm>
#include <cmath>

namespace FloorBlock::Verification
{
  namespace
  {
    constexpr dealii::types::material_id body           = 1;
    constexpr dealii::types::boundary_id contact_face   = 1;
    constexpr dealii::types::boundary_id symmetry_plane = 2;
    constexpr dealii::types::boundary_id loaded_face    = 3;
    /**
     * Cells finer than the contact cell size h0 = a / N cover the disc of
     * this many half-widths around the contact point, so that both ends
     * of the zone and the axis stresses down to 2a lie in cells of size h0.
     */
    constexpr double fine_zone_half_widths = 2.1;
    /**
     * Beyond that disc the cell size grows by this fraction of the
     * distance, h = h0 + g d. A refined band of fixed width instead (up to
     * 1.5 a, then 2:1 steps) left the contact width 0.25 % short of Hertz
     * whatever h0: the body just outside the zone was too stiff.
     */
    constexpr double cell_size_growth = 0.25;
    /** Geometric tolerance of face classification, relative to the body. */
    constexpr double face_tolerance = 1e-10;

    /**
     * The half model [0, W] x [0, W] of the elastic half-space, W =
     * hertz_body_half_widths a, refined around the contact point (the
     * origin) to cells of a / N within fine_zone_half_widths a, graded
     * beyond.
     */
    void
    make_half_space_block(const double              half_width,
                          const unsigned int        cells_per_half_width,
                          dealii::Triangulation<2> &mesh)
    {
      using namespace dealii;
      const double size = hertz_body_half_widths * half_width;
      GridGenerator::hyper_rectangle(mesh, Point<2>(), Point<2>(size, size));
      for (const auto &cell : mesh.active_cell_iterators())
        {
          cell->set_material_id(body);
          for (const auto &face : cell->face_iterators())
            {
              if (!face->at_boundary())
                continue;
              const Point<2> middle = face->center();
              if (std::abs(middle[1]) < face_tolerance * size)
                face->set_boundary_id(contact_face);
              else if (std::abs(middle[0]) < face_tolerance * size)
                face->set_boundary_id(symmetry_plane);
              else if (std::abs(middle[1] - size) < face_tolerance * size)
                face->set_boundary_id(loaded_face);
              else
                face->set_boundary_id(0); // the free far side x = W
            }
        }
      const double contact_cell_size = half_width / cells_per_half_width;
      bool         refined           = true;
      while (refined)
        {
          refined = false;
          for (const auto &cell : mesh.active_cell_iterators())
            {
              // Distance of the cell's nearest point to the fine disc.
              const double distance =
                std::max(0.,
                         cell->center().norm() - cell->diameter() / 2. -
                           fine_zone_half_widths * half_width);
              // Edge length of a square cell of this diameter, with a
              // margin for round-off of equal sizes.
              if (cell->diameter() / std::sqrt(2.) >
                  (1. + 1e-9) *
                    (contact_cell_size + cell_size_growth * distance))
                {
                  cell->set_refine_flag();
                  refined = true;
                }
            }
          if (refined)
            mesh.execute_coarsening_and_refinement();
        }
    }

    /**
     * sigma_x and sigma_z on the axis at depths a and 2a, computed and by
     * eq. 4.75. The axis is the symmetry plane x = 0, depth z = y. A depth
     * on a cell face (a and 2a are, on this mesh) takes the mean of the two
     * cells that share it: the FE stress jumps there, and the mean is the
     * face's second-order value.
     */
    std::vector<HertzAxisCheck>
    axis_checks(const Contact::ContactSolver<2> &solver,
                const Fem::ElasticModel<2>      &model,
                const HertzResult               &result)
    {
      std::vector<HertzAxisCheck> checks;
      const double                a = result.half_width_exact;
      for (const double depth : {a, 2. * a})
        {
          const double                        offset = 1e-9 * depth;
          const std::vector<Fem::PointStress> stresses =
            Fem::stresses_at_points(solver.space(),
                                    model,
                                    solver.solution(),
                                    {dealii::Point<2>(0., depth - offset),
                                     dealii::Point<2>(0., depth + offset)});
          const Analytic::HertzAxisStress exact =
            Analytic::hertz_axis_stress(result.peak_pressure_exact, a, depth);
          checks.push_back(
            {depth,
             exact.along_surface,
             exact.into_body,
             0.5 * (stresses[0].in_plane[0][0] + stresses[1].in_plane[0][0]),
             0.5 * (stresses[0].in_plane[1][1] + stresses[1].in_plane[1][1])});
        }
      return checks;
    }
  } // namespace

  HertzResult
  run_hertz_verification(const HertzSettings &settings)
  {
    const Material::ElasticLaw<2> law =
      Material::ElasticLaw<2>::from_youngs_poisson(settings.youngs_modulus,
                                                   settings.poissons_ratio);
    // Rigid counterpart: the contact modulus is the elastic body's
    // plane-strain modulus, 1/E* = (1 - nu^2)/E.
    const Analytic::HertzLineContact closed_form =
      Analytic::hertz_line_contact(settings.line_load,
                                   settings.radius,
                                   law.plane_strain_modulus());
    if (closed_form.status != Analytic::Status::ok)
      throw InputError("verify hertz: " +
                       Analytic::describe(closed_form.status));
    HertzResult result;
    result.half_width_exact    = closed_form.half_width;
    result.peak_pressure_exact = closed_form.peak_pressure;

    dealii::Triangulation<2> mesh;
    make_half_space_block(result.half_width_exact,
                          settings.cells_per_half_width,
                          mesh);
    Contact::ContactProblem<2> scene;
    scene.model.laws.emplace(body, law);
    // Half model: P/2 spread over the top face of width W.
    scene.model.pressures[loaded_face] =
      settings.line_load /
      (2. * hertz_body_half_widths * result.half_width_exact);
    Contact::SupportDefinition<2> symmetry;
    symmetry.boundary_id            = symmetry_plane;
    symmetry.constrained_components = {{true, false}};
    scene.supports                  = {symmetry};
    Contact::JointDefinition<2> contact;
    contact.name                        = "hertz";
    contact.side_a                      = contact_face;
    contact.law                         = settings.law;
    contact.parameters.normal_stiffness = settings.compliant_stiffness;
    contact.parameters.shear_stiffness  = settings.compliant_stiffness;
    contact.against_rigid_plane         = true;
    contact.plane_point                 = dealii::Point<2>();
    contact.plane_normal                = dealii::Tensor<1, 2>({0., -1.});
    contact.obstacle_curvature          = 1. / settings.radius;
    scene.joints                        = {contact};
    scene.steps                         = {0, 1, 0};

    Contact::ContactSolverSettings numerics;
    numerics.fe_degree   = settings.fe_degree;
    numerics.linear.kind = Solver::LinearSolverKind::direct;
    Contact::ContactSolver<2>  solver(mesh, scene, numerics);
    const Contact::SolveResult solved =
      Postprocess::solve_with_reports(solver, numerics);
    const Contact::JointReport &report = solved.increments.back().joints.at(0);
    result.n_dofs                      = solved.n_dofs;
    for (const Contact::IncrementResult &increment : solved.increments)
      result.n_newton_iterations += increment.n_newton_iterations;
    result.contact_force = 2. * report.normal_force;
    // The joint report's closed length, the estimate every joint table
    // prints (make_joint_reports(): the end from the square-root fall of
    // the exact law's traction): the half model's contact is [0, a].
    result.half_width_computed = report.closed_length;
    double last_closed         = 0.,
           first_open = hertz_body_half_widths * result.half_width_exact;
    for (const auto &sample : report.profile)
      {
        const double x = sample.position[0];
        if (sample.state != Contact::JointState::open)
          last_closed = std::max(last_closed, x);
        result.peak_pressure_computed =
          std::max(result.peak_pressure_computed, sample.normal_traction);
      }
    for (const auto &sample : report.profile)
      if (sample.state == Contact::JointState::open &&
          sample.position[0] > last_closed)
        first_open = std::min(first_open, sample.position[0]);
    result.last_closed_position = last_closed;
    result.contact_cell_size    = first_open - last_closed;

    result.axis = axis_checks(solver, scene.model, result);
    return result;
  }
} // namespace FloorBlock::Verification
