#include <output/gnuplot.h>

#include <fmt/format.h>
#include <studies/kn_safety_report.h>

namespace FloorBlock::Studies
{
  namespace
  {
    bool
    is_rigid(const KnSafetyCase &record)
    {
      return record.law == Contact::JointLawKind::rigid;
    }

    std::string
    optional_number(const std::optional<double> &value)
    {
      return value ? fmt::format("{:.9e}", *value) : "";
    }

    /** The x range: a decade's half either side of the swept kn. */
    constexpr double axis_margin = 2.;

    /** The resolved compliant cases as a gnuplot data block. */
    std::string
    compliant_data(const KnSafetySweep &sweep, unsigned int &n_rows)
    {
      std::string data = "$fs << EOD\n";
      n_rows           = 0;
      for (const KnSafetyCase &record : sweep.cases)
        if (!is_rigid(record) && record.point_factor)
          {
            data += fmt::format("{:.6e} {:.9e} {:.9e} {:.9e}\n",
                                record.normal_stiffness,
                                *record.point_factor,
                                *record.line_factor,
                                *record.area_factor);
            ++n_rows;
          }
      return data + "EOD\n";
    }
  } // namespace

  std::string
  kn_safety_csv(const KnSafetySweep &sweep)
  {
    std::string csv = fmt::format(
      "# Floor safety factor against the joints' normal stiffness "
      "(floorblock sweep --figure kn_safety): the governing floor-level "
      "corner's Hoek-Brown factor, point method at L/2, line method over L "
      "and area method within L (src/safety/), L = {:.6g} m, {} cells per L "
      "asked for; ks = {:.6g} kn (the scene's ks/kn); law rigid: exact "
      "contact, no kn or ks; the verdict (status) goes by verdict_method; "
      "the face corner is the face block's at the face joint\n"
      "kn_Pa_per_m,ks_Pa_per_m,law,safety_factor_point,safety_factor_line,"
      "safety_factor_area,verdict_method,status,governing_corner,"
      "face_corner_point,face_corner_line,face_corner_area,"
      "face_corner_status,mesh_cells\n",
      sweep.critical_distance,
      sweep.cells_per_critical_distance,
      sweep.stiffness_ratio);
    for (const KnSafetyCase &record : sweep.cases)
      csv += fmt::format(
        "{},{},{},{},{},{},{},{},{},{},{},{},{},{}\n",
        is_rigid(record) ? "" : fmt::format("{:.9e}", record.normal_stiffness),
        is_rigid(record) ? "" : fmt::format("{:.9e}", record.shear_stiffness),
        is_rigid(record) ? "rigid" : "compliant",
        optional_number(record.point_factor),
        optional_number(record.line_factor),
        optional_number(record.area_factor),
        record.verdict_method,
        record.status,
        record.governing_corner,
        optional_number(record.face_point_factor),
        optional_number(record.face_line_factor),
        optional_number(record.face_area_factor),
        record.face_status,
        record.n_cells);
    return csv;
  }

  std::string
  kn_safety_plot(const KnSafetySweep &sweep)
  {
    unsigned int      n_rows  = 0;
    const std::string data    = compliant_data(sweep, n_rows);
    const double      lowest  = kn_safety_normal_stiffnesses.front();
    const double      highest = kn_safety_normal_stiffnesses.back();
    std::string       script =
      data + fmt::format(
               "set logscale x\nset format x '%.0e'\nset xrange [{:g}:{:g}]\n"
               "set yrange [0:*]\nset grid\nset key outside right top\n"
               "set xlabel 'joint normal stiffness kn (Pa/m), ks = {:.3g} kn'\n"
               "set ylabel 'floor safety factor FS (governing corner)'\n"
               "set title 'Floor safety factor against kn'\n",
               lowest / axis_margin,
               highest * axis_margin,
               sweep.stiffness_ratio);

    std::vector<std::string> curves;
    if (n_rows > 0)
      {
        curves.push_back("$fs using 1:2 with linespoints lw 2 pt 7 lc "
                         "'#1b9e77' title 'point method (L/2)'");
        curves.push_back("$fs using 1:3 with linespoints lw 2 pt 5 lc "
                         "'#d95f02' title 'line method (mean over L)'");
        curves.push_back("$fs using 1:4 with linespoints lw 2 pt 9 lc "
                         "'#7570b3' title 'area method (mean within L)'");
      }
    for (const KnSafetyCase &record : sweep.cases)
      if (is_rigid(record) && record.point_factor)
        {
          curves.push_back(fmt::format("{:.9e} with lines dt 2 lw 2 lc "
                                       "'#1b9e77' title 'exact (rigid law), "
                                       "point'",
                                       *record.point_factor));
          curves.push_back(fmt::format("{:.9e} with lines dt 2 lw 2 lc "
                                       "'#d95f02' title 'exact (rigid law), "
                                       "line'",
                                       *record.line_factor));
          curves.push_back(fmt::format("{:.9e} with lines dt 2 lw 2 lc "
                                       "'#7570b3' title 'exact (rigid law), "
                                       "area'",
                                       *record.area_factor));
        }
    curves.push_back("1 with lines lw 1 lc 'black' title 'FS = 1'");

    script += "plot ";
    for (std::size_t k = 0; k < curves.size(); ++k)
      script += (k > 0 ? ", \\\n     " : "") + curves[k];
    return script + "\n";
  }

  std::string
  kn_safety_case_text(const KnSafetyCase &record)
  {
    const std::string law = is_rigid(record) ?
                              std::string("rigid law (exact)        ") :
                              fmt::format("kn = {:.0e} Pa/m (ks {:.2e})",
                                          record.normal_stiffness,
                                          record.shear_stiffness);
    if (!record.point_factor)
      return fmt::format("  {}: {}{}",
                         law,
                         record.status,
                         record.governing_corner.empty() ?
                           "" :
                           " at " + record.governing_corner);
    // The face corner where another corner governs.
    const std::string face =
      record.governing_corner.rfind("face block", 0) == 0 ?
        "" :
      record.face_point_factor ?
        fmt::format("; face corner {:.3f}, {:.3f}, {:.3f}",
                    *record.face_point_factor,
                    *record.face_line_factor,
                    *record.face_area_factor) :
        "; face corner " + record.face_status;
    return fmt::format(
      "  {}: FS = {:.3f} (point), {:.3f} (line), {:.3f} (area) at {}: {} "
      "(by the {} method){}",
      law,
      *record.point_factor,
      *record.line_factor,
      *record.area_factor,
      record.governing_corner,
      record.status,
      record.verdict_method,
      face);
  }

  void
  write_kn_safety(const Output::ResultFolder &folder,
                  const KnSafetySweep        &sweep)
  {
    folder.write("kn_safety.csv", kn_safety_csv(sweep));
    Output::render_png(kn_safety_plot(sweep),
                       folder.path_of("kn_safety.png"),
                       1100,
                       600);
  }
} // namespace FloorBlock::Studies
