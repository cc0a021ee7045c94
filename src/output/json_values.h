#pragma once

#include <nlohmann/json.hpp>

#include <optional>

namespace FloorBlock::Output
{
  /** @brief A value as JSON, or null where there is none. */
  inline nlohmann::json
  optional_json(const std::optional<double> &value)
  {
    return value ? nlohmann::json(*value) : nlohmann::json(nullptr);
  }

  /** @brief The inverse of optional_json(): null gives no value. */
  inline std::optional<double>
  optional_value(const nlohmann::json &value)
  {
    return value.is_null() ? std::nullopt :
                             std::optional<double>(value.get<double>());
  }
} // namespace FloorBlock::Output
