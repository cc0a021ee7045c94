#pragma once

namespace FloorBlock::Loading
{
  /** @brief Loading stage of the chapter's path, in the order applied. */
  enum class LoadStage
  {
    gravity,
    support_pressure,
    uplift
  };

  /**
   * @brief The stage's name in messages and failure records ("gravity",
   * "support load", "uplift"): one spelling for every model.
   */
  const char *
  stage_name(const LoadStage stage);
} // namespace FloorBlock::Loading
