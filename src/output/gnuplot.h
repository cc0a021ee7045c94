#pragma once

#include <string>

namespace FloorBlock::Output
{
  /**
   * @brief Renders a PNG with gnuplot (Debian package gnuplot-nox).
   *
   * @param[in] script gnuplot commands after the terminal is set; refer to
   * the output only through the terminal set here, and to data files by
   * absolute or folder-relative paths.
   * @param[in] png_path Final file; written atomically.
   * @param[in] width_pixels, height_pixels Image size.
   * @throws std::runtime_error if gnuplot is missing or fails (the message
   * carries gnuplot's own error output).
   */
  void
  render_png(const std::string &script,
             const std::string &png_path,
             const unsigned int width_pixels  = 900,
             const unsigned int height_pixels = 600);
} // namespace FloorBlock::Output
