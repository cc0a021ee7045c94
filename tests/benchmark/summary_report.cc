#include "summary_report.h"

#include <fmt/format.h>

#include <cmath>
#include <fstream>
#include <limits>
#include <set>

namespace FloorBlock::Benchmark
{
  namespace
  {
    constexpr double milliseconds_per_second = 1e3;
    constexpr double millimetres_per_metre   = 1e3;

    std::string
    pair_text(const StageTime &time, const double scale, const int digits)
    {
      return fmt::format("{:.{}f} / {:.{}f}",
                         scale * time.wall,
                         digits,
                         scale * time.cpu,
                         digits);
    }

    std::string
    stage_cell(const LevelRecord &level,
               const std::string &stage,
               const double       scale,
               const int          digits)
    {
      const auto found = level.stages.find(stage);
      return found == level.stages.end() ?
               "-" :
               pair_text(found->second, scale, digits);
    }

    std::string
    exponent_text(const double exponent)
    {
      return std::isfinite(exponent) ? fmt::format("{:.2f}", exponent) : "n/a";
    }

    std::string
    stage_table(const Records &all)
    {
      std::string text =
        "### Stages per mesh (wall / CPU)\n\n"
        "| r | cells | DoFs | pairs | linear solver | mesh (s) | assembly, "
        "cell matrices computed (ms) | assembly from cache (ms) | stored "
        "bulk copied + K u (ms) | one linear elastic solve (ms) | one Newton "
        "iteration (ms) |\n"
        "|---|---|---|---|---|---|---|---|---|---|---|\n";
      for (const auto &[r, level] : all.levels)
        text += fmt::format(
          "| {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} |\n",
          r,
          level.n_cells,
          level.n_dofs,
          level.n_contact_pairs,
          level.n_contact_pairs == 0 ? "-" :
          level.direct_solver        ? "KLU" :
                                       "GMRES+ML",
          stage_cell(level, "mesh", 1., 2),
          stage_cell(level, "assembly_cold", milliseconds_per_second, 1),
          stage_cell(level, "assembly_warm", milliseconds_per_second, 1),
          stage_cell(level, "bulk_reuse", milliseconds_per_second, 1),
          stage_cell(level, "linear_solve", milliseconds_per_second, 1),
          stage_cell(level, "newton_iteration", milliseconds_per_second, 1));
      return text;
    }

    std::string
    direct_phase_table(const Records &all)
    {
      std::string text =
        "\n### Direct solver phases on the same matrix (CPU, ms; KLU is "
        "the contact solver's)\n\n"
        "| solver | r | DoFs | symbolic | numeric | solve | numeric again "
        "(symbolic reused) | solve again (factors reused) |\n"
        "|---|---|---|---|---|---|---|---|\n";
      for (const std::string solver : {"KLU", "UMFPACK"})
        for (const auto &[r, level] : all.levels)
          {
            const auto phases = level.direct_phases.find(solver);
            if (phases == level.direct_phases.end())
              continue;
            const auto ms = [&](const std::string &phase) {
              return fmt::format("{:.1f}",
                                 milliseconds_per_second *
                                   phases->second.at(phase));
            };
            text += fmt::format("| {} | {} | {} | {} | {} | {} | {} | {} |\n",
                                solver,
                                r,
                                level.n_dofs,
                                ms("symbolic"),
                                ms("numeric"),
                                ms("solve"),
                                ms("numeric again"),
                                ms("solve again"));
          }
      return text;
    }

    std::set<std::string>
    laws_of(const Records &all)
    {
      std::set<std::string> laws;
      for (const auto &[r, level] : all.levels)
        for (const auto &[law, solve] : level.solves)
          laws.insert(law);
      return laws;
    }

    std::string
    solve_table(const Records &all)
    {
      std::string text =
        "\n### Whole contact solve (ContactSolver construction + run(), no "
        "output files)\n\n"
        "| law | r | DoFs | status | wall (s) | CPU (s) | increments | Newton "
        "iterations | cutbacks | face contact (mm) | "
        "solver's linear-solve section / Newton iterations (ms) | whole / one "
        "linear elastic solve (CPU) |\n"
        "|---|---|---|---|---|---|---|---|---|---|---|---|\n";
      for (const std::string &law : laws_of(all))
        for (const auto &[r, level] : all.levels)
          {
            const auto found = level.solves.find(law);
            if (found == level.solves.end())
              continue;
            const ContactSolveRecord &solve = found->second;
            const auto linear               = level.stages.find("linear_solve");
            const auto section = solve.sections.find("Contact: linear solve");
            text += fmt::format(
              "| {} | {} | {} | {} | {:.2f} | {:.2f} | {} | {} | {} | "
              "{:.1f} | {} | {} |\n",
              law,
              r,
              level.n_dofs,
              solve.converged ? "converged" : "failed: " + solve.failure,
              solve.time.wall,
              solve.time.cpu,
              solve.n_increments,
              solve.n_newton_iterations,
              solve.n_cutbacks,
              millimetres_per_metre * solve.face_contact_length,
              section == solve.sections.end() ||
                  solve.n_newton_iterations == 0 ?
                "-" :
                fmt::format("{:.1f}",
                            milliseconds_per_second * section->second /
                              solve.n_newton_iterations),
              linear == level.stages.end() ?
                "-" :
                fmt::format("{:.0f}", solve.time.cpu / linear->second.cpu));
          }
      return text;
    }

    std::string
    section_table(const Records &all)
    {
      std::set<std::string> names;
      for (const auto &[r, level] : all.levels)
        for (const auto &[law, solve] : level.solves)
          for (const auto &[name, seconds] : solve.sections)
            names.insert(name);
      std::string header = "| law | r |", rule = "|---|---|";
      for (const std::string &name : names)
        {
          header += " " + name + " |";
          rule += "---|";
        }
      std::string text = "\n### The contact solver's TimerOutput sections "
                         "(wall, s, and share of their sum)\n\n" +
                         header + "\n" + rule + "\n";
      for (const std::string &law : laws_of(all))
        for (const auto &[r, level] : all.levels)
          {
            const auto found = level.solves.find(law);
            if (found == level.solves.end())
              continue;
            double total = 0.;
            for (const auto &[name, seconds] : found->second.sections)
              total += seconds;
            text += fmt::format("| {} | {} |", law, r);
            for (const std::string &name : names)
              {
                const auto seconds = found->second.sections.find(name);
                text += seconds == found->second.sections.end() ?
                          " - |" :
                          fmt::format(" {:.3f} ({:.0f} %) |",
                                      seconds->second,
                                      100. * seconds->second / total);
              }
            text += "\n";
          }
      return text;
    }

    std::vector<std::pair<double, double>>
    stage_points(const Records &all, const std::string &stage, const bool cpu)
    {
      std::vector<std::pair<double, double>> points;
      for (const auto &[r, level] : all.levels)
        {
          const auto found = level.stages.find(stage);
          if (found != level.stages.end() && level.n_dofs > 0)
            points.emplace_back(level.n_dofs,
                                cpu ? found->second.cpu : found->second.wall);
        }
      return points;
    }

    std::vector<std::pair<double, double>>
    solve_points(const Records &all, const std::string &law, const bool cpu)
    {
      std::vector<std::pair<double, double>> points;
      for (const auto &[r, level] : all.levels)
        {
          const auto found = level.solves.find(law);
          if (found != level.solves.end() && found->second.converged)
            points.emplace_back(level.n_dofs,
                                cpu ? found->second.time.cpu :
                                      found->second.time.wall);
        }
      return points;
    }

    std::string
    fit_table(const Records &all)
    {
      std::string text =
        "\n### Fitted exponents p of time ~ DoFs^p (least squares in "
        "log-log over all measured levels)\n\n"
        "| quantity | levels | p (CPU) | p (wall) |\n|---|---|---|---|\n";
      const auto row = [&](const std::string &name, const auto &points_of) {
        text +=
          fmt::format("| {} | {} | {} | {} |\n",
                      name,
                      points_of(true).size(),
                      exponent_text(power_law_exponent(points_of(true))),
                      exponent_text(power_law_exponent(points_of(false))));
      };
      for (const std::string &law : laws_of(all))
        row("whole contact solve, " + law,
            [&](const bool cpu) { return solve_points(all, law, cpu); });
      for (const std::string stage :
           {"linear_solve", "newton_iteration", "assembly_warm", "mesh"})
        row(stage,
            [&](const bool cpu) { return stage_points(all, stage, cpu); });
      return text;
    }

    std::string
    contact_length_table(const Records &all)
    {
      std::string text;
      for (const std::string &law : laws_of(all))
        {
          const LevelRecord *finest = nullptr;
          for (const auto &[r, level] : all.levels)
            if (level.solves.count(law) && level.solves.at(law).converged)
              finest = &level;
          if (finest == nullptr)
            continue;
          const double reference = finest->solves.at(law).face_contact_length;
          text += fmt::format(
            "\n### Face-joint contact length, {} joints, against the finest "
            "level (r = {})\n\n"
            "| r | DoFs | contact (mm) | difference to finest (%) | mesh + "
            "solve (wall / CPU, s) |\n|---|---|---|---|---|\n",
            law,
            finest->refinement);
          for (const auto &[r, level] : all.levels)
            {
              const auto found = level.solves.find(law);
              if (found == level.solves.end() || !found->second.converged)
                continue;
              const double length = found->second.face_contact_length;
              StageTime    total  = found->second.time;
              if (level.stages.count("mesh"))
                {
                  total.wall += level.stages.at("mesh").wall;
                  total.cpu += level.stages.at("mesh").cpu;
                }
              text +=
                fmt::format("| {} | {} | {:.1f} | {} | {} |\n",
                            r,
                            level.n_dofs,
                            millimetres_per_metre * length,
                            reference > 0. ?
                              fmt::format("{:+.1f}",
                                          100. * (length / reference - 1.)) :
                              "-",
                            pair_text(total, 1., 2));
            }
        }
      return text;
    }

    std::string
    hertz_table(const Records &all)
    {
      if (all.hertz.empty())
        return "";
      std::string text =
        "\n### Hertz verification (run_hertz_verification, rigid law)\n\n"
        "| cells per half-width | DoFs | Newton iterations | wall "
        "(s) | CPU (s) | half-width error (%) | peak pressure error (%) |\n"
        "|---|---|---|---|---|---|---|\n";
      for (const auto &[cells, hertz] : all.hertz)
        text += hertz.failure.empty() ?
                  fmt::format("| {} | {} | {} | {:.2f} | {:.2f} | "
                              "{:+.2f} | {:+.2f} |\n",
                              cells,
                              hertz.n_dofs,
                              hertz.n_newton_iterations,
                              hertz.time.wall,
                              hertz.time.cpu,
                              100. * hertz.half_width_error,
                              100. * hertz.peak_pressure_error) :
                  fmt::format("| {} | failed: {} |\n", cells, hertz.failure);
      return text;
    }
  } // namespace

  double
  power_law_exponent(const std::vector<std::pair<double, double>> &points)
  {
    if (points.size() < 2)
      return std::numeric_limits<double>::quiet_NaN();
    double mean_x = 0., mean_y = 0.;
    for (const auto &[n, t] : points)
      {
        mean_x += std::log(n) / points.size();
        mean_y += std::log(t) / points.size();
      }
    double covariance = 0., variance = 0.;
    for (const auto &[n, t] : points)
      {
        covariance += (std::log(n) - mean_x) * (std::log(t) - mean_y);
        variance += (std::log(n) - mean_x) * (std::log(n) - mean_x);
      }
    return variance > 0. ? covariance / variance :
                           std::numeric_limits<double>::quiet_NaN();
  }

  std::string
  load_average()
  {
    std::ifstream file("/proc/loadavg");
    std::string   line;
    std::getline(file, line);
    return line;
  }

  std::string
  summary_markdown(const Records &all, const RunContext &context)
  {
    std::string blas_files;
    for (const std::string &library : context.blas.libraries)
      blas_files += (blas_files.empty() ? "" : ", ") + library;
    std::string text = fmt::format(
      "## FloorBlock benchmark summary\n\n"
      "- {} cores; /proc/loadavg at start: {}; at end: {}\n"
      "- BLAS: {} ({}){}\n"
      "- one thread (deal.II thread limit 1, OpenBLAS 1 thread); times are "
      "wall / process CPU\n\n",
      context.n_cores,
      context.load_before,
      context.load_after,
      context.blas.name,
      blas_files,
      context.blas.limited_to_one_thread ? ", limited to one thread" : "");
    return text + stage_table(all) + direct_phase_table(all) +
           solve_table(all) + section_table(all) + fit_table(all) +
           contact_length_table(all) + hertz_table(all);
  }
} // namespace FloorBlock::Benchmark
