#include "output_checks.h"

#include <analytic/status.h>

#include <cmath>
#include <cstdlib>
#include <regex>
#include <set>
#include <sstream>

namespace FloorBlock::Fuzz
{
  namespace
  {
    // Status is an enum class (underlying int); probing this many values
    // covers any plausible growth of the enum without listing its members.
    constexpr int n_probed_status_values = 256;

    const std::set<std::string> &
    known_statuses()
    {
      static const std::set<std::string> names = [] {
        std::set<std::string> collected;
        for (int value = 0; value < n_probed_status_values; ++value)
          {
            const std::string name =
              Analytic::to_string(static_cast<Analytic::Status>(value));
            if (name != "unknown")
              collected.insert(name);
          }
        return collected;
      }();
      return names;
    }

    bool
    ends_with(const std::string &text, const std::string &suffix)
    {
      return text.size() >= suffix.size() &&
             text.compare(text.size() - suffix.size(), suffix.size(), suffix) ==
               0;
    }

    void
    collect_json_defects(const nlohmann::json     &node,
                         const std::string        &path,
                         std::vector<std::string> &defects)
    {
      if (node.is_null())
        defects.push_back(path + " is null (NaN/inf written by nlohmann?)");
      else if (node.is_number_float() && !std::isfinite(node.get<double>()))
        defects.push_back(path + " is not finite");
      else if (node.is_object())
        for (const auto &[key, child] : node.items())
          {
            const std::string child_path = path + "/" + key;
            if ((key == "status" || ends_with(key, "_status")) &&
                !(child.is_string() &&
                  is_known_status(child.get<std::string>())))
              defects.push_back(child_path + " = " + child.dump() +
                                " is not a known status");
            collect_json_defects(child, child_path, defects);
          }
      else if (node.is_array())
        for (std::size_t i = 0; i < node.size(); ++i)
          collect_json_defects(node[i],
                               path + "[" + std::to_string(i) + "]",
                               defects);
    }

    std::vector<std::string>
    split(const std::string &text, const char delimiter)
    {
      std::vector<std::string> pieces;
      std::string              piece;
      std::istringstream       stream(text);
      while (std::getline(stream, piece, delimiter))
        pieces.push_back(piece);
      if (!text.empty() && text.back() == delimiter)
        pieces.emplace_back();
      return pieces;
    }

    bool
    is_finite_number(const std::string &cell)
    {
      char        *end   = nullptr;
      const double value = std::strtod(cell.c_str(), &end);
      return end != cell.c_str() && *end == '\0' && std::isfinite(value);
    }

    void
    check_finite(const std::vector<double> &values,
                 const std::string         &name,
                 std::vector<std::string>  &defects)
    {
      for (std::size_t i = 0; i < values.size(); ++i)
        if (!std::isfinite(values[i]))
          defects.push_back(name + "[" + std::to_string(i) +
                            "] = " + std::to_string(values[i]));
    }

    void
    check_finite(const double              value,
                 const std::string        &name,
                 std::vector<std::string> &defects)
    {
      check_finite(std::vector<double>{value}, name, defects);
    }

    void
    check_status(const Analytic::Status    status,
                 const std::string        &name,
                 std::vector<std::string> &defects)
    {
      if (!is_known_status(Analytic::to_string(status)))
        defects.push_back(name + " has no known status value");
    }
  } // namespace

  bool
  is_known_status(const std::string &name)
  {
    return known_statuses().count(name) == 1;
  }

  std::vector<std::string>
  json_defects(const nlohmann::json &report)
  {
    std::vector<std::string> defects;
    collect_json_defects(report, "", defects);
    return defects;
  }

  std::vector<std::string>
  csv_defects(const std::string &csv)
  {
    std::vector<std::string> defects;
    std::vector<std::string> header;
    std::size_t              line_number = 0;
    for (const std::string &line : split(csv, '\n'))
      {
        ++line_number;
        if (line.empty() || line.front() == '#')
          continue;
        const std::vector<std::string> cells = split(line, ',');
        if (header.empty())
          {
            header = cells;
            continue;
          }
        const std::string where = "csv line " + std::to_string(line_number);
        if (cells.size() != header.size())
          {
            defects.push_back(where + " has " + std::to_string(cells.size()) +
                              " cells, the header " +
                              std::to_string(header.size()));
            continue;
          }
        for (std::size_t column = 0; column < cells.size(); ++column)
          {
            const std::string &cell = cells[column];
            if (ends_with(header[column], "_status"))
              {
                if (!is_known_status(cell))
                  defects.push_back(where + " " + header[column] + " = '" +
                                    cell + "' is not a known status");
              }
            else if (!cell.empty() && !is_finite_number(cell))
              defects.push_back(where + " " + header[column] + " = '" + cell +
                                "' is not a finite number");
          }
      }
    if (header.empty())
      defects.push_back("csv has no header line");
    return defects;
  }

  std::vector<std::string>
  table_defects(const std::string &table)
  {
    // fmt prints non-finite doubles as nan / inf, possibly signed; words
    // such as "infinite" in the status sentences must not match.
    static const std::regex non_finite(
      "(^|[^A-Za-z_])[-+]?(nan|inf)([^A-Za-z_]|$)", std::regex::icase);
    std::vector<std::string> defects;
    std::smatch              match;
    if (std::regex_search(table, match, non_finite))
      defects.push_back(
        "table prints a non-finite number near '" +
        table.substr(match.position(0) > 40 ? match.position(0) - 40 : 0, 80) +
        "'");
    return defects;
  }

  std::vector<std::string>
  closed_form_defects(const Scene::ClosedForms &closed_forms)
  {
    std::vector<std::string> defects;
    const auto              &chain = closed_forms.chain;
    check_finite(chain.weight, "chain.weight", defects);
    check_finite(chain.support_load, "chain.support_load", defects);
    check_finite(chain.inclination, "chain.inclination", defects);
    check_finite(closed_forms.floor_lift, "floor_lift", defects);
    check_finite(closed_forms.youngs_modulus, "youngs_modulus", defects);
    for (const auto &entry : closed_forms.mechanisms)
      {
        const std::string name   = Scene::to_string(entry.mechanism);
        const auto       &forces = entry.forces;
        check_status(forces.status, name + ".status", defects);
        check_status(entry.contact.status, name + ".contact.status", defects);
        check_finite(forces.lateral_force, name + ".Q", defects);
        check_finite(forces.normal_force, name + ".N", defects);
        check_finite(forces.joint_shear, name + ".V", defects);
        check_finite(forces.normal_force_offset, name + ".offset", defects);
        check_finite(entry.face_force_over_width, name + ".Q_over_b", defects);
        check_finite(entry.contact.contact_area, name + ".A", defects);
        check_finite(entry.contact.contact_length, name + ".c", defects);
        check_finite(entry.contact.average_stress,
                     name + ".sigma_avg",
                     defects);
        check_finite(entry.contact.max_stress, name + ".sigma_max", defects);
      }
    const auto &heights = closed_forms.no_rotation_heights;
    check_status(heights.status, "no_rotation_heights.status", defects);
    check_finite(heights.centroid_height, "h", defects);
    check_finite(heights.rotation_margin, "H - h", defects);
    return defects;
  }
} // namespace FloorBlock::Fuzz
