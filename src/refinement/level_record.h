#pragma once

#include <cstddef>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace FloorBlock::Refinement
{
  /** @brief One level of a refinement ladder: its mesh, cost and answers. */
  struct LevelRecord
  {
    std::string  mode; ///< "uniform", "adaptive" or "remesh"
    unsigned int level = 0;
    /** "converged", "not converged" (loading path not completed) or "failed"
     * (mesh or solver error). */
    std::string status;
    std::string status_text;

    /** Base size function h(d) = min(far, corner + (growth - 1) d) of the level
     * (m, m, 1). */
    double corner_size = 0.;
    double far_size    = 0.;
    double growth_rate = 0.;
    /** Times every cell of that Gmsh mesh was halved (uniform: grows by one per
     * level). */
    unsigned int global_refinements = 0;
    /** Adaptive and remesh: number of solution-driven size requests the mesh
     * honours. */
    std::size_t n_local_sizes = 0;
    /** Adaptive: refinement sweeps that made this level's mesh from the
     * previous one. */
    unsigned int n_refinement_sweeps = 0;
    /** Adaptive: cells of the previous level removed by coarsening (children of
     * coarsened parents). */
    std::size_t n_cells_coarsened = 0;

    std::size_t  n_cells           = 0;
    unsigned int n_dofs            = 0;
    unsigned int n_contact_pairs   = 0;
    unsigned int n_increments      = 0;
    unsigned int newton_iterations = 0;
    unsigned int cutbacks          = 0;
    /** Worst relative force imbalance over the converged increments (1). */
    double force_balance_error = 0.;

    /** Wall time per stage (s): "mesh", the solver's "Contact: ..." sections,
     * "indicator". */
    std::map<std::string, double> stage_wall_times;
    /** Wall time of this level (s). */
    double wall_time = 0.;
    /**
     * Wall time needed to obtain this level's answer from nothing (s):
     * the level itself for uniform refinement, all levels so far for
     * adaptive refinement (each needs the solution of the one before).
     */
    double cost_wall_time = 0.;

    /** Normal force Q_i of vertical joints 1..n, chapter numbering (N/m). */
    std::vector<double> joint_normal_forces;
    /** Face joint (vertical joint n): closed length (m), pointwise and averaged
     * peak normal stress (Pa). */
    double face_contact_length     = 0.;
    double face_sigma_max          = 0.;
    double face_sigma_max_averaged = 0.;

    bool
    converged() const
    {
      return status == "converged";
    }
  };

  /** @brief A quantity of interest: output name, unit suffix, value. */
  struct Quantity
  {
    std::string name; ///< e.g. "Q_face", "contact_length_face"
    std::string unit; ///< column suffix, e.g. "N_per_m", "m", "Pa"
    std::function<double(const LevelRecord &)> value;
  };

  /**
   * @brief Q at every vertical joint (Q_1 .. Q_{n-1}, and Q_face for joint
   * n), face-joint contact length, pointwise and averaged sigma_max.
   */
  std::vector<Quantity>
  quantities_of_interest(const unsigned int n_blocks);

  /** @brief The quantity on every level; empty where the level did not converge. */
  std::vector<std::optional<double>>
  quantity_series(const std::vector<LevelRecord> &levels,
                  const Quantity                 &quantity);
} // namespace FloorBlock::Refinement
