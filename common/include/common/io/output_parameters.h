/**
 * @file output_parameters.h
 * The "Output" subsection: where results go and what is written. Owns the
 * result directory (creation and removal of stale result files); writes no
 * results itself.
 */
#ifndef common_io_output_parameters_h
#define common_io_output_parameters_h

#include <common/io/console.h>

#include <deal.II/base/parameter_handler.h>

#include <string>
#include <vector>

namespace Common
{
  namespace IO
  {
    /**
     * @brief Parameters of subsection "Output".
     */
    struct OutputParameters
    {
      /** @brief Declare the entries of subsection "Output". */
      static void
      declare_parameters(dealii::ParameterHandler &prm);

      /** @brief Read the entries of subsection "Output" and check them. */
      void
      parse_parameters(dealii::ParameterHandler &prm);

      /**
       * @brief Create the output directory and remove the result files named
       * in @p result_files that an earlier run left there, so that a failing
       * run never leaves results that look valid. Collective over
       * @p mpi_communicator; rank 0 touches the file system.
       */
      void
      prepare_directory(const std::vector<std::string> &result_files,
                        const MPI_Comm                  mpi_communicator) const;

      /** @brief Path of @p file_name inside the output directory. */
      std::string
      path(const std::string &file_name) const;

      std::string directory;
      /** Boundary ids whose reaction forces are written to reactions.csv
       * after every accepted step (empty: no file). */
      std::vector<unsigned int> reaction_boundary_ids;
      bool                      write_graphical_output;
      bool                      write_plots;
      Verbosity                 verbosity;
    };
  } // namespace IO
} // namespace Common

#endif
