#pragma once

#include <contact/contact_problem.h>
#include <contact/joint_law.h>
#include <contact/newton_driver.h>
#include <geometry/assembly_description.h>

#include <vector>

namespace FloorBlock::RigidBlocks
{
  /** @brief Numerical settings of the rigid-block solver. */
  struct RigidSolverSettings
  {
    /**
     * Integration points per joint (trapezoid rule, end points included),
     * >= 2. A contact zone shorter than the point spacing is missed, so the
     * spacing H/(n - 1) must resolve the shortest contact length of
     * interest (the corner contact of Eq. 6.51 is a few cm long).
     */
    unsigned int n_points_per_joint = 400;
    /**
     * Newton controls. Every joint law here is piecewise linear in the block
     * motions (small rotations, Coulomb in 2D), so once the stick/slip/open
     * set is right one more step reaches round-off. The round-off floor of
     * the residual is about eps kn |u| per point, summed over the points:
     * measured 4e-6 N/m at kn = 1e12 Pa/m with 5 cm of base travel, i.e.
     * 1e-12 of the default loads, so 1e-12 cannot be demanded for stiff
     * joints; 1e-10 (relative to the larger of the load norm and the first
     * residual of the increment) is reachable up to kn = 1e14 Pa/m. The
     * independent force balance (IncrementReport::relative_imbalance)
     * reports what was actually reached.
     */
    Contact::NewtonSettings newton = [] {
      Contact::NewtonSettings settings;
      settings.relative_tolerance = 1e-10;
      return settings;
    }();
    /**
     * When the consistent tangent is singular because the closed points of
     * a block all slip, the Newton direction is computed once more with
     * this fraction of ks added as shear stiffness at slipping points (-).
     * This is a search direction only (the residual is unchanged): it lets
     * an iterate that overshot into an all-slip state come back, while a
     * true mechanism still never converges and is reported as
     * SolveStatus::no_equilibrium. 0 disables it.
     */
    double slip_stabilisation = 1e-2;
    /** Halvings of a failed increment before the solve gives up. */
    unsigned int max_cutbacks = 8;
    /**
     * A pivot below this fraction of the largest diagonal entry of the
     * tangent counts as singular (-). Round-off in the LU of a regular
     * tangent stays near 1e-16 of it; a mechanism gives exactly zero up to
     * round-off.
     */
    double singular_pivot_tolerance = 1e-12;
    /**
     * Keep the point profiles of every converged increment (true), not only
     * of the last one: the scene pipeline needs them for the averaged peak
     * stress along the lift (about 50 bytes per point and increment).
     */
    bool profiles_of_every_increment = false;
  };

  /**
   * @brief Everything the rigid-block model needs: the same scene
   * description as the FE model (geometry, joint laws, uplift, load steps)
   * plus the loads of the rigid blocks. SI units, forces per metre of face.
   */
  struct ModelDescription
  {
    /** Blocks, face block and bedding profile (lengths in m). */
    Geometry::AssemblyDescription assembly;
    /** Rock density of the blocks (kg/m^3). */
    double density = 2500.;
    /** Magnitude of the gravity acceleration, acting in -y (m/s^2). */
    double gravity = 9.81;
    /**
     * Powered-support line load on the top of block i, index i - 1
     * (chapter numbering), vertical, downwards (N/m). Empty = no support
     * load; otherwise one entry per block.
     */
    std::vector<double> support_line_loads;
    /**
     * Where the resultant of a support load acts on the block top, as a
     * fraction of L from the block's side away from the face (the uphill
     * side): 0.5 = centre, as for a uniform pressure (the convention of
     * Analytic::BlockChain::support_load_position) (-).
     */
    double support_load_position = 0.5;
    /** kn, ks, friction angle phi_h, cohesion, tension of the bedding. */
    Contact::JointConstants bedding_joint;
    /** kn, ks, friction angle phi_v, cohesion, tension of vertical joints. */
    Contact::JointConstants vertical_joint;
    /** Prescribed motion of the (rigid) base in the uplift stage. */
    Contact::UpliftSettings uplift;
    /** Increments of the gravity, support-load and uplift stages. */
    Loading::LoadSteps  steps;
    RigidSolverSettings solver;
  };

  /**
   * @brief Refuse a description the model cannot solve.
   * @throws FloorBlock::InputError naming the offending entry.
   */
  void
  validate(const ModelDescription &description);
} // namespace FloorBlock::RigidBlocks
