#include <common/io/console.h>

#include <iomanip>
#include <iostream>
#include <sstream>

namespace Common
{
  namespace IO
  {
    Console::Console(const Verbosity verbosity, const MPI_Comm mpi_communicator)
      : verbosity(verbosity)
      , root(dealii::Utilities::MPI::this_mpi_process(mpi_communicator) == 0)
      , quiet_stream(std::cout, root)
      , normal_stream(std::cout, root && verbosity != Verbosity::quiet)
      , verbose_stream(std::cout, root && verbosity == Verbosity::verbose)
    {}



    dealii::ConditionalOStream &
    Console::stream(const Verbosity level)
    {
      switch (level)
        {
          case Verbosity::quiet:
            return quiet_stream;
          case Verbosity::normal:
            return normal_stream;
          default:
            return verbose_stream;
        }
    }



    void
    Console::print_quantity(const std::string &label,
                            const std::string &unit,
                            const double       value,
                            const std::string &ratio_label,
                            const double       ratio)
    {
      std::ostringstream line;
      const std::string  name = label + (unit.empty() ? "" : " [" + unit + "]");
      line << "  " << std::left << std::setw(44) << name << std::right
           << std::setw(13) << format(value);
      if (!ratio_label.empty())
        line << "   " << ratio_label << " " << std::fixed
             << std::setprecision(4) << ratio;
      normal_stream << line.str() << std::endl;
    }



    std::string
    Console::format(const double value)
    {
      std::ostringstream s;
      // Print exact zeros as zero: -0 and 1e-300 noise would otherwise make
      // the output depend on the platform.
      s << std::scientific << std::setprecision(5)
        << (std::abs(value) < 1e-300 ? 0. : value);
      return s.str();
    }



    bool
    Console::is_root() const
    {
      return root;
    }
  } // namespace IO
} // namespace Common
