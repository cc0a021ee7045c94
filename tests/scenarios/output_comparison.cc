#include "output_comparison.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <vector>

#include "process.h"

namespace FloorBlockTest
{
  bool
  is_skipped_field(const std::string &name)
  {
    // Wall-clock seconds and ratios of them, the only machine-dependent
    // numbers floorblock writes; each is named so: wall_time_s (a total, or
    // an object of seconds per stage), wall_time_s_per_stage,
    // wall_time_<stage>_s (convergence.csv), cost_wall_time_s and
    // cost_wall_time_ratio_adaptive_over_uniform (converge).
    if (name.find("wall_time") != std::string::npos)
      return true;
    // converge's verdicts whether the adaptive / remesh ladder beats the
    // uniform one: the status needs a wall-time ratio below 1 and the text
    // prints it ("time x0.777"). The DoF ratios and errors they are made of
    // are compared in equal_error_comparison.
    if (name == "adaptive_target" || name == "remesh_target")
      return true;
    // summary.json's echo of the expanded parameters (parameters.prm's
    // text): a parameter added to the program, or a derived value noted
    // beside its entry, changes this text without changing a result, and
    // the scene's values enter every number that is compared.
    if (name == "inputs")
      return true;
    // What the solution cost, not what it is: Newton iterations, linear
    // solves, LU factorisations kept or renewed, Krylov iterations. A
    // factorisation is reused while GMRES on it converges within a cap and
    // Newton stops on a residual test, so these counts follow round-off:
    // another machine's BLAS kernels (OpenBLAS picks them per CPU) moved
    // them by 1-40 % (2026-11-26) with every result within tolerance.
    static const std::set<std::string> cost_counters = {
      "newton_iterations",
      "failed_newton_iterations",
      "linear_solves",
      "lu_factorizations",
      "krylov_iterations_on_lu_factors",
      "linear_solves_above_tolerance",
      "amg_setups",
      "krylov_iterations_with_amg"};
    return cost_counters.count(name) > 0;
  }

  namespace
  {
    using nlohmann::json;

    /** At most this many differences are listed per file, then a count. */
    constexpr std::size_t max_listed_differences = 20;

    std::string
    number_text(const double value)
    {
      std::ostringstream text;
      text.precision(17);
      text << value;
      return text.str();
    }

    /** The tolerance of @p field: its declared looser one, else the default. */
    /**
     * Residuals that are round-off by nature, in every case: the force
     * balance of a solution converged to Newton's relative tolerance 1e-10
     * of loads near 1e6 N/m leaves up to 1e-4 N/m, and a different order of
     * sums (another machine's BLAS) moves it anywhere below that (measured:
     * 1e-7 against 5e-7 N/m on two machines).
     */
    const std::vector<FieldTolerance> &
    round_off_fields()
    {
      static const std::vector<FieldTolerance> fields = {
        {"force_balance_absolute_error_N_per_m",
         {1e-4, 1e-8},
         "Newton tolerance 1e-10 x loads of 1e6 N/m"},
        {"force_balance_relative_error",
         {1e-10, 1e-8},
         "Newton's relative tolerance"}};
      return fields;
    }

    /** Skipped everywhere (is_skipped_field) or in this case. */
    bool
    skipped(const std::string &field, const ComparisonSettings &settings)
    {
      return is_skipped_field(field) ||
             std::find(settings.skipped_fields.begin(),
                       settings.skipped_fields.end(),
                       field) != settings.skipped_fields.end();
    }

    Tolerance
    tolerance_of(const std::string &field, const ComparisonSettings &settings)
    {
      for (const FieldTolerance &looser : settings.looser_fields)
        if (looser.field == field)
          return looser.tolerance;
      for (const FieldTolerance &round_off : round_off_fields())
        if (round_off.field == field)
          return round_off.tolerance;
      return settings.tolerance;
    }

    /** numdiff's rule: equal if within the absolute or the relative bound. */
    bool
    numbers_equal(const double a, const double b, const Tolerance &tolerance)
    {
      if (!std::isfinite(a) || !std::isfinite(b))
        return (std::isnan(a) && std::isnan(b)) || a == b;
      const double difference = std::abs(a - b);
      return difference <= tolerance.absolute ||
             difference <=
               tolerance.relative * std::max(std::abs(a), std::abs(b));
    }

    std::string
    number_difference(const double a, const double b)
    {
      const double difference = std::abs(a - b);
      const double scale      = std::max(std::abs(a), std::abs(b));
      return " (absolute difference " + number_text(difference) +
             ", relative " +
             (scale > 0. ? number_text(difference / scale) : std::string("-")) +
             ")";
    }

    /** Collects differences, listing the first few and counting the rest. */
    class DifferenceList
    {
    public:
      explicit DifferenceList(const std::string &file)
        : file(file)
      {}

      void
      add(const std::string &where, const std::string &what)
      {
        ++n_differences;
        if (n_differences <= max_listed_differences)
          listed.push_back(file + ": " + where + ": " + what);
      }

      std::vector<std::string>
      result() const
      {
        std::vector<std::string> differences = listed;
        if (n_differences > max_listed_differences)
          differences.push_back(
            file + ": " +
            std::to_string(n_differences - max_listed_differences) +
            " further differences not listed");
        return differences;
      }

    private:
      std::string              file;
      std::vector<std::string> listed;
      std::size_t              n_differences = 0;
    };

    /**
     * Walks @p reference and @p output together; @p field is the nearest
     * object key above the value (the name its tolerance is declared by).
     */
    void
    compare_json_values(const json               &reference,
                        const json               &output,
                        const std::string        &pointer,
                        const std::string        &field,
                        const ComparisonSettings &settings,
                        DifferenceList           &differences)
    {
      const std::string where = pointer.empty() ? "/" : pointer;
      if (reference.is_number() && output.is_number())
        {
          const double a = reference.get<double>();
          const double b = output.get<double>();
          if (!numbers_equal(a, b, tolerance_of(field, settings)))
            differences.add(where,
                            "reference " + number_text(a) + ", output " +
                              number_text(b) + number_difference(a, b));
          return;
        }
      if (reference.type() != output.type())
        {
          differences.add(where,
                          "reference " + reference.dump() + " (" +
                            reference.type_name() + "), output " +
                            output.dump() + " (" + output.type_name() + ")");
          return;
        }
      if (reference.is_object())
        {
          // An entry that names its quantity (summary.json's
          // face_joint_figures: {"field": "contact_length_m", "value": ...})
          // compares its value under that name.
          const std::string named_field =
            reference.contains("field") && reference["field"].is_string() ?
              reference["field"].get<std::string>() :
              std::string();
          for (const auto &item : reference.items())
            {
              const std::string name =
                item.key() == "value" && !named_field.empty() ? named_field :
                                                                item.key();
              if (skipped(name, settings))
                continue;
              const std::string child = pointer + "/" + item.key();
              if (!output.contains(item.key()))
                differences.add(child, "key missing in the output");
              else
                compare_json_values(item.value(),
                                    output.at(item.key()),
                                    child,
                                    name,
                                    settings,
                                    differences);
            }
          for (const auto &item : output.items())
            if (!skipped(item.key(), settings) &&
                !reference.contains(item.key()))
              differences.add(pointer + "/" + item.key(),
                              "key not in the reference (output " +
                                item.value().dump() + ")");
          return;
        }
      if (reference.is_array())
        {
          if (reference.size() != output.size())
            differences.add(where,
                            "reference has " +
                              std::to_string(reference.size()) +
                              " entries, output " +
                              std::to_string(output.size()));
          const std::size_t n = std::min(reference.size(), output.size());
          for (std::size_t k = 0; k < n; ++k)
            compare_json_values(reference[k],
                                output[k],
                                pointer + "/" + std::to_string(k),
                                field,
                                settings,
                                differences);
          return;
        }
      // Strings, booleans and nulls: equal or not.
      if (reference != output)
        differences.add(where,
                        "reference " + reference.dump() + ", output " +
                          output.dump());
    }

    /** @p text as a number if the whole of it is one (strtod's syntax). */
    bool
    parse_number(const std::string &text, double &value)
    {
      if (text.empty())
        return false;
      char *end = nullptr;
      value     = std::strtod(text.c_str(), &end);
      return end == text.c_str() + text.size();
    }

    /** The '#' comment lines of a CSV file, which read_csv skips. */
    std::vector<std::string>
    comment_lines(const std::string &path)
    {
      std::ifstream            in(path);
      std::vector<std::string> lines;
      for (std::string line; std::getline(in, line);)
        if (!line.empty() && line[0] == '#')
          lines.push_back(line);
      return lines;
    }

    std::string
    joined(const std::vector<std::string> &fields)
    {
      std::string text;
      for (const std::string &field : fields)
        text += (text.empty() ? "" : ",") + field;
      return text;
    }
  } // namespace

  std::vector<std::string>
  compare_json(const nlohmann::json     &reference,
               const nlohmann::json     &output,
               const std::string        &file,
               const ComparisonSettings &settings)
  {
    DifferenceList differences(file);
    compare_json_values(reference, output, "", "", settings, differences);
    return differences.result();
  }

  std::vector<std::string>
  compare_csv(const std::string        &reference_path,
              const std::string        &output_path,
              const std::string        &file,
              const ComparisonSettings &settings)
  {
    DifferenceList differences(file);

    const auto reference_comments = comment_lines(reference_path);
    const auto output_comments    = comment_lines(output_path);
    if (reference_comments != output_comments)
      for (std::size_t k = 0;
           k < std::max(reference_comments.size(), output_comments.size());
           ++k)
        {
          const std::string a =
            k < reference_comments.size() ? reference_comments[k] : "(none)";
          const std::string b =
            k < output_comments.size() ? output_comments[k] : "(none)";
          if (a != b)
            differences.add("comment line " + std::to_string(k + 1),
                            "reference \"" + a + "\", output \"" + b + "\"");
        }

    const CsvTable reference = read_csv(reference_path);
    const CsvTable output    = read_csv(output_path);
    if (reference.columns != output.columns)
      {
        differences.add("header",
                        "reference \"" + joined(reference.columns) +
                          "\", output \"" + joined(output.columns) + "\"");
        return differences.result();
      }
    if (reference.rows.size() != output.rows.size())
      differences.add("rows",
                      "reference has " + std::to_string(reference.rows.size()) +
                        " rows, output " + std::to_string(output.rows.size()));

    const std::size_t n_rows =
      std::min(reference.rows.size(), output.rows.size());
    for (std::size_t r = 0; r < n_rows; ++r)
      for (const std::string &column : reference.columns)
        {
          if (skipped(column, settings))
            continue;
          const std::string where =
            "row " + std::to_string(r + 1) + ", column " + column;
          const auto a_field = reference.rows[r].find(column);
          const auto b_field = output.rows[r].find(column);
          if (a_field == reference.rows[r].end() ||
              b_field == output.rows[r].end())
            {
              if (a_field != reference.rows[r].end() ||
                  b_field != output.rows[r].end())
                differences.add(where,
                                std::string("field missing in the ") +
                                  (a_field == reference.rows[r].end() ?
                                     "reference" :
                                     "output"));
              continue;
            }
          const std::string &a = a_field->second;
          const std::string &b = b_field->second;
          double             x = 0., y = 0.;
          if (parse_number(a, x) && parse_number(b, y))
            {
              if (!numbers_equal(x, y, tolerance_of(column, settings)))
                differences.add(where,
                                "reference " + a + ", output " + b +
                                  number_difference(x, y));
            }
          else if (a != b)
            differences.add(where,
                            "reference \"" + a + "\", output \"" + b + "\"");
        }
    return differences.result();
  }

  std::vector<std::string>
  compare_files(const std::string        &reference_path,
                const std::string        &output_path,
                const std::string        &file,
                const ComparisonSettings &settings)
  {
    for (const auto &[path, which] :
         {std::pair{reference_path, "reference"}, {output_path, "output"}})
      if (!std::filesystem::is_regular_file(path))
        return {file + ": the " + which + " file " + path + " is missing"};

    const std::string extension =
      std::filesystem::path(file).extension().string();
    if (extension == ".json")
      {
        json reference, output;
        try
          {
            reference = read_json(reference_path);
            output    = read_json(output_path);
          }
        catch (const json::exception &error)
          {
            return {file + ": not valid JSON: " + error.what()};
          }
        return compare_json(reference, output, file, settings);
      }
    if (extension == ".csv")
      return compare_csv(reference_path, output_path, file, settings);
    if (read_text(reference_path) != read_text(output_path))
      return {file + ": the files differ (compared byte for byte)"};
    return {};
  }
} // namespace FloorBlockTest
