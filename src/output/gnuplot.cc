#include <common/atomic_file.h>
#include <output/gnuplot.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace FloorBlock::Output
{
  void
  render_png(const std::string &script,
             const std::string &png_path,
             const unsigned int width_pixels,
             const unsigned int height_pixels)
  {
    const std::string temporary_png  = temporary_name_for(png_path);
    const std::string script_path    = temporary_png + ".gp";
    const std::string error_log_path = temporary_png + ".log";
    {
      std::ofstream out(script_path);
      out << "set terminal pngcairo noenhanced size " << width_pixels << ","
          << height_pixels << " font 'sans,11'\n"
          << "set output '" << temporary_png << "'\n"
          << script << "\nunset output\n";
    }
    const std::string command =
      "gnuplot '" + script_path + "' 2> '" + error_log_path + "'";
    const int status = std::system(command.c_str());

    std::stringstream gnuplot_errors;
    gnuplot_errors << std::ifstream(error_log_path).rdbuf();
    std::error_code ignored;
    std::filesystem::remove(script_path, ignored);
    std::filesystem::remove(error_log_path, ignored);

    if (status != 0 || !std::filesystem::exists(temporary_png))
      {
        std::filesystem::remove(temporary_png, ignored);
        throw std::runtime_error("gnuplot failed for " + png_path + ": " +
                                 gnuplot_errors.str());
      }
    commit_temporary_file(temporary_png, png_path);
  }
} // namespace FloorBlock::Output
