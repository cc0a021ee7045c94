#pragma once

#include <output/case_store.h>
#include <output/fem_report.h>
#include <output/result_folder.h>
#include <scene/chapter_figures.h>

#include <nlohmann/json.hpp>

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace FloorBlock::Output
{
  /** A closed form's answer at the face joint of one sweep case. */
  struct FemCaseClosedForm
  {
    std::string           status;         ///< of the chain equations
    std::optional<double> face_force;     ///< Q_n (N/m); none: no finite Q
    std::optional<double> max_stress;     ///< Eq. 6.53 (Pa); none: no answer
    std::string           contact_status; ///< of Eqs. 6.51-6.53
    /// The chapter's route: sigma_c / max_stress; none where max_stress is
    /// none or not positive (Scene::MechanismResult::floor_safety_factor).
    std::optional<double> safety_factor;
  };

  /**
   * The FEM's floor safety at the face corner, the face block's corner at
   * the face joint (Safety::CornerSafety): the point method's stress and
   * factor at L/2 along the corner's bisector, numbers only where the mesh
   * resolves the critical distance L.
   */
  struct FemFaceCorner
  {
    /// "resolved"; else why there is no number: "unresolved", "not
    /// converged", "not evaluated" (no stress field: rigid blocks) or "not
    /// recorded" (a case file from before the corner was stored).
    std::string           status = "not recorded";
    std::optional<double> sigma_1;      ///< at L/2 (Pa, compression > 0)
    std::optional<double> point_factor; ///< FS, point method
  };

  /**
   * The record of one FEM sweep case: its inputs, the FEM's face joint and
   * face corner, the scene rock's strength and each closed form's Q_n,
   * sigma_max (Eq. 6.53, geometric y) and safety factor for the same
   * inputs. Stored as cases/<id>.json (fem_case_json()).
   */
  struct FemCaseRecord
  {
    std::string id;
    std::string figure;
    double      curvature             = 0.; ///< k (m); 0 for a planar bed
    double      bedding_friction_deg  = 0.; ///< phi_h (deg), as written
    double      vertical_friction_deg = 0.; ///< phi_v (deg), as written
    double      support_load_t        = 0.; ///< support load (t), as written
    std::string status;      ///< the FEM's: "converged" or "not converged"
    std::string status_text; ///< why, in words
    std::string model;       ///< "elastic FEM" or "rigid blocks"
    /** The face joint's figures; none without a converged increment. */
    std::optional<double>         face_force;              ///< Q_n (N/m)
    std::optional<double>         face_contact_length;     ///< m
    std::optional<double>         face_sigma_max;          ///< Pa, pointwise
    std::optional<double>         face_sigma_max_averaged; ///< Pa
    FemFaceCorner                 face_corner;
    unsigned int                  n_dofs = 0;
    std::map<std::string, double> wall_times; ///< s, per solver section
    /// The rock mass's uniaxial strength sigma_c (Pa,
    /// Scene::ClosedForms::floor_strength); none in older case files.
    std::optional<double> floor_strength;
    /** By mechanism name (Scene::to_string). */
    std::map<std::string, FemCaseClosedForm> closed_forms;
  };

  /** @brief The record of one solved sweep case. */
  FemCaseRecord
  fem_case_record(const Scene::FigurePoint   &point,
                  const Contact::SolveResult &result,
                  const FemReport            &report);

  /** @brief The case file's JSON: units in the keys, null where absent. */
  nlohmann::json
  fem_case_json(const FemCaseRecord &record);

  /**
   * @brief A case file read back by the resume store (fem_case_json()'s
   * inverse; a missing "model" means the elastic FEM, a missing face
   * corner, strength or safety factor leaves it not recorded).
   */
  FemCaseRecord
  fem_case_from_json(const nlohmann::json &case_json);

  /** @brief One CSV row per case of @p figure; units in the column names. */
  std::string
  fem_sweep_csv(const std::vector<FemCaseRecord> &records,
                const std::string                &figure);

  /**
   * @brief gnuplot script shaped like the chapter's figure: Q at the face
   * (Figures 6.5-6.7, one panel per vertical friction) or sigma_max at the
   * face (Figures 6.10/6.11, one panel per curvature), against bedding
   * friction; FEM as points, closed forms as lines. Figures 6.10/6.11 also
   * draw the FEM's sigma_1 at L/2 at the face corner (open points) and the
   * rock mass strength sigma_c (dashed).
   */
  std::string
  fem_sweep_plot(const std::vector<FemCaseRecord> &records,
                 const std::string                &figure);

  /**
   * @brief Reads the finished cases among @p case_ids from @p store and
   * writes, per figure they belong to, sweep_fem_<figure>.csv and .png
   * into @p folder.
   * @return The number of finished cases.
   */
  std::size_t
  write_fem_sweep(const CaseStore                &store,
                  const std::vector<std::string> &case_ids,
                  const ResultFolder             &folder);
} // namespace FloorBlock::Output
