#include <parameters/sections.h>
#include <parameters/value_text.h>

namespace FloorBlock::Parameters
{
  using dealii::ParameterHandler;
  using dealii::Patterns::Double;
  using dealii::Patterns::Integer;
  using dealii::Patterns::Selection;

  namespace
  {
    /** The FE degree and the load path's increments. */
    void
    declare_load_path(ParameterHandler &prm)
    {
      prm.declare_entry(
        "FE degree",
        "auto",
        Selection("auto|1|2"),
        "Polynomial degree of the FE_Q displacement space, or auto: `run` "
        "picks the degree that meets Mesh/Target relative error sooner. It "
        "solves degree 1's level 0 and its check; unless that pair meets the "
        "target (then no degree-2 solve on the same mesh could be faster), "
        "degree 2's loop joins, and the two loops take turns, the one with "
        "less time spent solving next, until one meets the target "
        "(src/studies/degree_race.h). Both loops share Mesh/Refinement "
        "time budget. Where the joints act as exact contact (the rigid law, "
        "or E/kn below Geometry/Corner rounding radius) degree 1 runs alone: "
        "the displacement is not smooth where contact zones end, and degree "
        "2 converges no faster there. "
        "Degree 2's solves are under <output>/fe_degree_2/. Every other "
        "command solves with degree 1 when auto (verify hertz: degree 1 at "
        "32 cells per half-width meets its tolerances in less time than "
        "degree 2 at 16). Units: none.");
      prm.declare_entry("Gravity steps",
                        "1",
                        Integer(1, 1000),
                        "Load increments of stage 1 (gravity). Units: none.");
      prm.declare_entry("Gravity with support load",
                        "false",
                        dealii::Patterns::Bool(),
                        "true: gravity rises together with the support load "
                        "over the Support load steps (stage 1 of the six-block "
                        "benchmark, params/s6.prm) and Gravity steps is not "
                        "used; false: gravity first, then the support load. "
                        "Units: none.");
      prm.declare_entry("Support load steps",
                        "2",
                        Integer(1, 1000),
                        "Load increments of stage 2 (support pressure). "
                        "Units: none.");
      prm.declare_entry("Uplift steps",
                        "10",
                        Integer(1, 10000),
                        "Load increments of stage 3 (floor uplift); friction "
                        "is path dependent, so this is part of the model. "
                        "Units: none.");
    }

    /** The linear solver of the Newton systems. */
    void
    declare_linear_solver(ParameterHandler &prm)
    {
      prm.declare_entry("Linear solver",
                        "automatic",
                        Selection("automatic|direct|iterative"),
                        "automatic: sparse direct (Amesos KLU) up to 'Max "
                        "direct DoFs', ML AMG + GMRES above; or force either. "
                        "Units: none.");
      prm.declare_entry("Max direct DoFs",
                        "400000",
                        Integer(1, 100000000),
                        "Largest system that 'automatic' solves directly. "
                        "Newton keeps the LU factors and reuses them, so "
                        "direct wins far above one solve's break-even: "
                        "default scene, 79k DoFs, 16 s against 90 s with ML "
                        "AMG + GMRES; 312k DoFs direct in 81 s and 2.5 GB. "
                        "3D scenes: at most 80000, where UMFPACK's fill "
                        "makes GMRES + ML as fast (Scene::max_direct_dofs_3d). "
                        "Units: none.");
      prm.declare_entry("Direct solver",
                        "automatic",
                        Selection("automatic|KLU|UMFPACK"),
                        "Sparse LU of the contact Newton solves: Amesos KLU, "
                        "SuiteSparse UMFPACK (multifrontal, BLAS 3: three "
                        "times faster at 57k DoFs with OpenBLAS, slower below "
                        "about 8k), or automatic = UMFPACK from 8000 DoFs on. "
                        "Units: none.");
      prm.declare_entry("Factorization reuse iterations",
                        "20",
                        Integer(0, 1000),
                        "Direct solver: GMRES iterations tried with the LU "
                        "factors of an earlier Newton matrix before the "
                        "current one is factorised afresh; 0 factorises every "
                        "Newton matrix. Changes cost only: every solve meets "
                        "the same residual tolerance. Units: none.");
    }

    /** Newton's tolerance and limits, the joints' averaging length, the
     * complementarity parameter and the error estimate. */
    void
    declare_newton_and_estimate(ParameterHandler &prm)
    {
      prm.declare_entry("Newton tolerance",
                        "1e-10",
                        Double(1e-15, 1e-2),
                        "An increment has converged when the residual norm is "
                        "below this fraction of the reference force (the "
                        "larger of the applied load norm and the first "
                        "residual) and the stick/slip/open set is unchanged. "
                        "Units: none (relative).");
      prm.declare_entry(
        "Max Newton iterations",
        "100",
        Integer(1, 10000),
        "Newton iterations allowed per increment. Units: none.");
      prm.declare_entry("Max cutbacks",
                        "6",
                        Integer(0, 30),
                        "Halvings of a failed increment before the run stops "
                        "with 'not converged'. Units: none.");
      prm.declare_entry("Averaging length",
                        "0.05",
                        Double(1e-6, 10),
                        "Length along a joint over which the averaged peak "
                        "normal stress is taken (the pointwise peak does not "
                        "converge at sharp corners). Units: m.");
      prm.declare_entry(
        "Complementarity factor",
        "0.1",
        Double(1e-3, 1e6),
        "Rigid law: the complementarity parameter of each joint "
        "node pair, this factor times E over the pair's length "
        "(at least the smallest cell diameter). It shapes the "
        "Newton iterates of the exact contact law, not its "
        "answer: 0.1 took the fewest iterations on the floor "
        "scenes (params/s6.prm: 51 at 0.1, 193 at 1; at 10 "
        "the support stage fails). A load state whose every "
        "start fails is tried once more with a tenth of it "
        "before a cutback, and a rescued state keeps the "
        "tenth for the rest of the solve (at most a "
        "hundredth). Units: none.");
      prm.declare_entry("Error estimate",
                        "refined solve",
                        Selection("refined solve|none"),
                        "How `run` estimates the discretisation error of each "
                        "FEM figure: refined solve = the difference to a solve "
                        "on the next adaptive level of the same mesh "
                        "(src/studies/adaptive_levels.h), repeated until "
                        "Mesh/Target relative error is met (the rigid-block "
                        "model: one solve with twice the points per joint); "
                        "none = one solve, no estimate. Units: none.");
    }

  } // namespace

  void
  SolverParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Solver");
    declare_load_path(prm);
    declare_linear_solver(prm);
    declare_newton_and_estimate(prm);
    prm.leave_subsection();
  }

  void
  SolverParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Solver");
    const std::string degree  = prm.get("FE degree");
    choose_fe_degree          = degree == "auto";
    fe_degree                 = choose_fe_degree ?
                                  1 :
                                  selected_count(degree, "Solver/FE degree", "auto, 1 or 2");
    n_gravity_steps           = prm.get_integer("Gravity steps");
    gravity_with_support_load = prm.get_bool("Gravity with support load");
    n_support_steps           = prm.get_integer("Support load steps");
    n_uplift_steps            = prm.get_integer("Uplift steps");
    const std::string solver  = prm.get("Linear solver");
    linear_solver   = solver == "direct" ? Solver::LinearSolverKind::direct :
                      solver == "iterative" ?
                                           Solver::LinearSolverKind::iterative :
                                           Solver::LinearSolverKind::automatic;
    max_direct_dofs = prm.get_integer("Max direct DoFs");
    max_reuse_iterations   = prm.get_integer("Factorization reuse iterations");
    const std::string lu   = prm.get("Direct solver");
    direct_solver          = lu == "KLU"     ? Solver::DirectSolverKind::klu :
                             lu == "UMFPACK" ? Solver::DirectSolverKind::umfpack :
                                               Solver::DirectSolverKind::automatic;
    newton_tolerance       = prm.get_double("Newton tolerance");
    max_newton_iterations  = prm.get_integer("Max Newton iterations");
    max_cutbacks           = prm.get_integer("Max cutbacks");
    averaging_length       = prm.get_double("Averaging length");
    complementarity_factor = prm.get_double("Complementarity factor");
    estimate_error_by_refined_solve =
      prm.get("Error estimate") == "refined solve";
    prm.leave_subsection();
  }
} // namespace FloorBlock::Parameters
