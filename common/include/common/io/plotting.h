/**
 * @file plotting.h
 * PNG line plots of CSV columns through gnuplot. The gnuplot script is kept
 * beside the PNG, so a plot can be restyled and redrawn by hand.
 */
#ifndef common_io_plotting_h
#define common_io_plotting_h

#include <string>
#include <utility>
#include <vector>

namespace Common
{
  namespace IO
  {
    /**
     * @brief One curve: columns of a CSV file with a header line.
     */
    struct PlotSeries
    {
      /** CSV file, relative to the plot's directory. */
      std::string data_file;
      /** 1-based column numbers of x and y. */
      unsigned int x_column;
      unsigned int y_column;
      /** Legend entry. */
      std::string title;
      /** gnuplot style, e.g. "lines lw 2" or "points pt 7 ps 0.6". */
      std::string style;
    };

    /**
     * @brief Description of one x-y plot.
     */
    struct PlotDescription
    {
      std::string             title;
      std::string             x_label;
      std::string             y_label;
      std::vector<PlotSeries> series;
      /** Optional x range "[xmin:xmax]"; empty for automatic. */
      std::string x_range;
      /** Log-log axes. */
      bool log_log = false;
      /** Optional y range "[ymin:ymax]"; empty for automatic. */
      std::string y_range;
      /** One unit of x as long as one unit of y on the page (shapes). */
      bool equal_axes = false;
    };

    /**
     * @brief Write `<directory>/<name>.gp` and run gnuplot to produce
     * `<directory>/<name>.png`.
     * @return true if the PNG was produced; false if gnuplot is missing or
     * failed (the script is still written, and a PNG gnuplot left behind
     * is removed).
     */
    bool
    write_plot(const std::string     &directory,
               const std::string     &name,
               const PlotDescription &plot);

    /** @brief True if a gnuplot executable is found on the PATH. */
    bool
    gnuplot_available();

    /**
     * @brief Write each named plot with write_plot() into @p directory.
     * @return The names of the plots without a PNG (all of them if gnuplot
     * is missing; the scripts are written).
     */
    std::vector<std::string>
    write_plots(
      const std::string                                          &directory,
      const std::vector<std::pair<std::string, PlotDescription>> &plots);
  } // namespace IO
} // namespace Common

#endif
