#pragma once

#include <contact/results.h>
#include <rigid/model.h>
#include <rigid/results.h>

namespace FloorBlock::RigidBlocks
{
  /**
   * @brief The converged increments of a rigid-block solve in the result
   * structures of the contact FEM, so that one set of report writers and
   * comparisons (fem.json, joints.csv, `run`) serves both models.
   *
   * Per joint (same names, "vertical j" and "bedding i"):
   * - normal force, contact length (cut at the zero of the interpolated
   *   overlap), mean traction and stick/slip/open counts as the rigid model
   *   integrated them;
   * - shear force and profile tractions converted to the FEM's sign: along
   *   the tangent (-n_y, n_x) of the FEM normal, which points from block
   *   j+1 (or the face block) into block j, and from the base into the
   *   block. On a vertical joint that is the chapter's V_j (the downward
   *   force on block j) as in the rigid model; on the bedding it is the
   *   force on the block away from the face, the opposite of the rigid
   *   model's sign;
   * - pointwise and averaged peak from the point profile with
   *   Postprocess::add_peak_stresses(), the FEM's own definition;
   * Per increment: stage factor of the increment's stage, Newton
   * iterations, cutbacks, residual; block motions keyed by material id
   * (Geometry::Ids: blocks 1..n, face block with zero motion; the base is
   * no rigid body and is left out); the force balance with the rigid
   * model's per-block imbalance (stricter than the FEM's global one) and,
   * as applied load and reaction, the block loads and the contact forces
   * of the fixed bodies (face block, base) on the blocks.
   * Whole solve: n_dofs = 3 per block, n_contact_pairs = 0 (the rigid
   * model integrates points, it has no node pairs), one wall time
   * "Rigid blocks: solve".
   *
   * @param[in] rigid Result of Model::solve() with the profiles of every
   * increment (RigidSolverSettings::profiles_of_every_increment); an
   * increment without profiles gets zero peaks.
   * @param[in] model The model that produced @p rigid (joint geometry and
   * loads).
   * @param[in] averaging_length Window of the averaged peak (m).
   */
  Contact::SolveResult
  to_contact_result(const RigidSolveResult &rigid,
                    const Model            &model,
                    const double            averaging_length);
} // namespace FloorBlock::RigidBlocks
