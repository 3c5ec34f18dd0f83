/**
 * @file console.h
 * The only place that formats numbers for standard output. Standard output
 * is the test oracle: fixed formats, rank 0 only, no timings or paths.
 */
#ifndef common_io_console_h
#define common_io_console_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/mpi.h>

#include <string>

namespace Common
{
  namespace IO
  {
    /** Values of the parameter "Verbosity" in subsection "Output". */
    enum class Verbosity
    {
      quiet,
      normal,
      verbose
    };

    /**
     * @brief Console output of rank 0 with a verbosity level.
     */
    class Console
    {
    public:
      /**
       * @param[in] verbosity Level above which messages are dropped.
       * @param[in] mpi_communicator Only rank 0 of this communicator prints.
       */
      Console(const Verbosity verbosity, const MPI_Comm mpi_communicator);

      /** @brief Stream that prints at level @p level or below. */
      dealii::ConditionalOStream &
      stream(const Verbosity level = Verbosity::normal);

      /**
       * @brief Print "  <label> [<unit>]   <value>" with 6 significant
       * digits, optionally followed by "<ratio_label> <ratio>" with 4
       * decimals.
       */
      void
      print_quantity(const std::string &label,
                     const std::string &unit,
                     const double       value,
                     const std::string &ratio_label = "",
                     const double       ratio       = 0.);

      /** @brief Format @p value with 6 significant digits, scientific. */
      static std::string
      format(const double value);

      /** @brief True on the rank that prints. */
      bool
      is_root() const;

    private:
      const Verbosity            verbosity;
      const bool                 root;
      dealii::ConditionalOStream quiet_stream;
      dealii::ConditionalOStream normal_stream;
      dealii::ConditionalOStream verbose_stream;
    };
  } // namespace IO
} // namespace Common

#endif
