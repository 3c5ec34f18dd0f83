/**
 * @file solution_output.h
 * ParaView output: one .vtu per rank and step, a .pvtu per step and one
 * .pvd for the run, into the output directory. Fields: displacement, any
 * postprocessed quantities (e.g. stress) and nodal scalar fields (e.g.
 * contact pressure).
 */
#ifndef common_io_solution_output_h
#define common_io_solution_output_h

#include <common/io/output_parameters.h>

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/lac/vector.h>
#include <deal.II/numerics/data_postprocessor.h>

#include <map>
#include <string>
#include <utility>
#include <vector>

namespace Common
{
  namespace IO
  {
    /**
     * @brief A scalar nodal field to add to the output.
     */
    struct NodalScalarField
    {
      std::string name;
      /** Value per global DoF of the first displacement component. */
      std::map<dealii::types::global_dof_index, double> values;
    };

    /**
     * @brief Writes the steps of a run for ParaView.
     */
    template <int dim>
    class SolutionOutput
    {
    public:
      /**
       * @param[in] parameters Output directory and switches.
       * @param[in] base_name File name stem, e.g. "solution".
       */
      SolutionOutput(const OutputParameters &parameters,
                     const std::string      &base_name,
                     const MPI_Comm          mpi_communicator);

      /**
       * @brief Write one step.
       * @param[in] u Displacement (mm), ghosted.
       * @param[in] postprocessors Derived quantities (e.g. stress).
       * @param[in] scalar_fields Nodal fields given at displacement nodes.
       * @param[in] time Pseudo-time of the step (load factor).
       */
      void
      write(const dealii::DoFHandler<dim>               &dof_handler,
            const dealii::Mapping<dim>                  &mapping,
            const dealii::TrilinosWrappers::MPI::Vector &u,
            const std::vector<const dealii::DataPostprocessor<dim> *>
                                                &postprocessors,
            const std::vector<NodalScalarField> &scalar_fields,
            const double                         time,
            const unsigned int                   step);

    private:
      const OutputParameters                     &parameters;
      const std::string                           base_name;
      const MPI_Comm                              mpi_communicator;
      std::vector<std::pair<double, std::string>> records;
    };
  } // namespace IO
} // namespace Common

#endif
