#include <common/io/plotting.h>

#include <deal.II/base/exceptions.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>

namespace Common
{
  namespace IO
  {
    bool
    gnuplot_available()
    {
      return std::system("command -v gnuplot >/dev/null 2>&1") == 0;
    }



    bool
    write_plot(const std::string     &directory,
               const std::string     &name,
               const PlotDescription &plot)
    {
      const std::filesystem::path dir(directory);
      {
        std::ofstream gp(dir / (name + ".gp"));
        AssertThrow(gp, dealii::ExcMessage("Cannot write plot script " + name));
        gp << "set terminal pngcairo size 900,600 enhanced font 'Sans,11'\n"
           << "set output '" << name << ".png'\n"
           << "set datafile separator ','\n"
           << "set key top right box opaque\n"
           << "set grid\n"
           << "set title \"" << plot.title << "\"\n"
           << "set xlabel \"" << plot.x_label << "\"\n"
           << "set ylabel \"" << plot.y_label << "\"\n";
        if (plot.log_log)
          gp << "set logscale xy\n";
        if (!plot.x_range.empty())
          gp << "set xrange " << plot.x_range << "\n";
        if (!plot.y_range.empty())
          gp << "set yrange " << plot.y_range << "\n";
        if (plot.equal_axes)
          gp << "set size ratio -1\n";
        gp << "plot ";
        for (unsigned int i = 0; i < plot.series.size(); ++i)
          {
            const auto &s = plot.series[i];
            gp << (i > 0 ? ", \\\n     " : "") << "'" << s.data_file
               << "' every ::1 using " << s.x_column << ":" << s.y_column
               << " with " << s.style << " title \"" << s.title << "\"";
          }
        gp << "\n";
      }
      if (!gnuplot_available())
        return false;
      const std::string command = "cd '" + dir.string() + "' && gnuplot '" +
                                  name + ".gp' >/dev/null 2>&1";
      if (std::system(command.c_str()) == 0)
        return true;
      std::error_code ignored;
      std::filesystem::remove(dir / (name + ".png"), ignored);
      return false;
    }


    std::vector<std::string>
    write_plots(
      const std::string                                          &directory,
      const std::vector<std::pair<std::string, PlotDescription>> &plots)
    {
      std::vector<std::string> missing;
      for (const auto &[name, plot] : plots)
        if (!write_plot(directory, name, plot))
          missing.push_back(name);
      return missing;
    }
  } // namespace IO
} // namespace Common
