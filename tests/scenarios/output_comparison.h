#pragma once

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace FloorBlockTest
{
  /**
   * @brief numdiff-style tolerance of one number: two numbers are equal when
   * \f$|a - b| \le\f$ @p absolute or
   * \f$|a - b| \le\f$ @p relative \f$\max(|a|, |b|)\f$ (numdiff's default,
   * as ASPECT's `diff_test.sh` uses it). Defaults: STYLE.md §6.
   */
  struct Tolerance
  {
    double absolute = 1e-10;
    double relative = 1e-8;
  };

  /**
   * @brief A looser tolerance for one field (a JSON key anywhere in the tree,
   * or a CSV column), with the reason it is needed (STYLE.md §6: "looser
   * values must be declared per test, with a reason").
   */
  struct FieldTolerance
  {
    std::string field;
    Tolerance   tolerance;
    std::string reason;
  };

  /** @brief How one scenario's output files are compared. */
  struct ComparisonSettings
  {
    Tolerance                   tolerance;
    std::vector<FieldTolerance> looser_fields;
    /**
     * Fields (JSON keys, CSV columns) this case does not compare; the case
     * says why next to the list.
     */
    std::vector<std::string> skipped_fields;
  };

  /**
   * @brief True for the fields never compared because their values depend on
   * the machine or the moment, not on the numbers the tool computes: JSON
   * keys (at any depth, with everything below them) and CSV columns. The
   * list is short on purpose; output_comparison.cc says why for each entry.
   */
  bool
  is_skipped_field(const std::string &name);

  /**
   * @brief Differences between a reference JSON tree and an output one:
   * same keys, same structure, strings/booleans/nulls equal, numbers within
   * tolerance; keys for which is_skipped_field() holds are
   * ignored. Each difference names
   * @p file, the JSON pointer of the value and both values.
   */
  std::vector<std::string>
  compare_json(const nlohmann::json     &reference,
               const nlohmann::json     &output,
               const std::string        &file,
               const ComparisonSettings &settings = {});

  /**
   * @brief Differences between a reference CSV file and an output one (read
   * by read_csv of tests/cli/process.h): same '#' comment lines, same header,
   * same number of rows, every field present, numeric fields within
   * tolerance, other fields equal; columns for which
   * is_skipped_field() holds are ignored.
   * Each difference names @p file, the row (1 = first data row), the column
   * and both values.
   */
  std::vector<std::string>
  compare_csv(const std::string        &reference_path,
              const std::string        &output_path,
              const std::string        &file,
              const ComparisonSettings &settings = {});

  /**
   * @brief Compares two files by their extension (.json or .csv; any other
   * file must be equal byte for byte). A missing or unreadable file is a
   * difference. The report names @p file (the name relative to the case
   * folder).
   */
  std::vector<std::string>
  compare_files(const std::string        &reference_path,
                const std::string        &output_path,
                const std::string        &file,
                const ComparisonSettings &settings = {});
} // namespace FloorBlockTest
