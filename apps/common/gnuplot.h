#pragma once

#include <filesystem>
#include <string>

namespace compax::cli
{
  /**
   * Renders a PNG with gnuplot (Debian package gnuplot-nox): writes the
   * script next to the data so users can edit and re-run it, then runs
   * gnuplot in the output folder. Plotting is a convenience: if gnuplot is
   * missing or fails, a warning is printed and the run goes on.
   *
   * @param folder where the data files are and the PNG goes
   * @param script_name e.g. "contact.gp"
   * @param script gnuplot commands; the terminal and output are prepended
   * @param png_name e.g. "contact.png"
   * @return whether the PNG was written
   */
  bool
  render_png(const std::filesystem::path &folder,
             const std::string           &script_name,
             const std::string           &script,
             const std::string           &png_name);
} // namespace compax::cli
