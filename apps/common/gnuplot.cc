#include "apps/common/gnuplot.h"

#include <cstdlib>
#include <fstream>
#include <iostream>

namespace compax::cli
{
  bool
  render_png(const std::filesystem::path &folder,
             const std::string           &script_name,
             const std::string           &script,
             const std::string           &png_name)
  {
    {
      std::ofstream out(folder / script_name);
      out << "set terminal pngcairo size 1200,800 font 'Sans,11'\n"
          << "set output '" << png_name << "'\n"
          << "set datafile separator ','\n"
          << "set key autotitle columnhead\n"
          << "set grid\n"
          << script;
    }
    if (std::system("command -v gnuplot > /dev/null 2>&1") != 0)
      {
        std::cerr << "warning: gnuplot not found, " << png_name
                  << " not drawn (apt-get install gnuplot-nox); the script "
                  << script_name << " is in the output folder\n";
        return false;
      }
    const std::string command = "cd '" + folder.string() + "' && gnuplot '"
                                + script_name + "' > gnuplot.log 2>&1";
    if (std::system(command.c_str()) != 0)
      {
        std::cerr << "warning: gnuplot failed on " << script_name
                  << ", see gnuplot.log in the output folder\n";
        return false;
      }
    std::filesystem::remove(folder / "gnuplot.log");
    return true;
  }
} // namespace compax::cli
