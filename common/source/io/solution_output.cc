#include <common/io/solution_output.h>

#include <deal.II/fe/fe_q.h>
#include <deal.II/numerics/data_out.h>

#include <fstream>

namespace Common
{
  namespace IO
  {
    using namespace dealii;

    template <int dim>
    SolutionOutput<dim>::SolutionOutput(const OutputParameters &parameters,
                                        const std::string      &base_name,
                                        const MPI_Comm mpi_communicator)
      : parameters(parameters)
      , base_name(base_name)
      , mpi_communicator(mpi_communicator)
    {}



    template <int dim>
    void
    SolutionOutput<dim>::write(
      const DoFHandler<dim>                             &dof_handler,
      const Mapping<dim>                                &mapping,
      const TrilinosWrappers::MPI::Vector               &u,
      const std::vector<const DataPostprocessor<dim> *> &postprocessors,
      const std::vector<NodalScalarField>               &scalar_fields,
      const double                                       time,
      const unsigned int                                 step)
    {
      // Scalar fields live on a scalar element of the same degree: its
      // shape function i sits on the node of displacement shape function
      // (component 0, i).
      const FiniteElement<dim> &fe = dof_handler.get_fe();
      DoFHandler<dim> scalar_dof_handler(dof_handler.get_triangulation());
      scalar_dof_handler.distribute_dofs(fe.base_element(0));
      std::vector<Vector<double>> scalar_vectors(
        scalar_fields.size(),
        Vector<double>(scalar_dof_handler.n_dofs()));
      {
        std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
        std::vector<types::global_dof_index> scalar_dofs(
          fe.base_element(0).n_dofs_per_cell());
        auto scalar_cell = scalar_dof_handler.begin_active();
        for (const auto &cell : dof_handler.active_cell_iterators())
          {
            cell->get_dof_indices(dofs);
            scalar_cell->get_dof_indices(scalar_dofs);
            for (unsigned int i = 0; i < scalar_dofs.size(); ++i)
              {
                const auto dof = dofs[fe.component_to_system_index(0, i)];
                for (unsigned int k = 0; k < scalar_fields.size(); ++k)
                  {
                    const auto it = scalar_fields[k].values.find(dof);
                    if (it != scalar_fields[k].values.end())
                      scalar_vectors[k](scalar_dofs[i]) = it->second;
                  }
              }
            ++scalar_cell;
          }
      }

      DataOut<dim> data_out;
      data_out.attach_dof_handler(dof_handler);
      const std::vector<std::string> names(dim, "displacement");
      const std::vector<
        DataComponentInterpretation::DataComponentInterpretation>
        interpretation(
          dim,
          DataComponentInterpretation::component_is_part_of_vector);
      data_out.add_data_vector(u,
                               names,
                               DataOut<dim>::type_dof_data,
                               interpretation);
      for (const auto *postprocessor : postprocessors)
        data_out.add_data_vector(u, *postprocessor);
      for (unsigned int k = 0; k < scalar_fields.size(); ++k)
        data_out.add_data_vector(scalar_dof_handler,
                                 scalar_vectors[k],
                                 scalar_fields[k].name);

      Vector<float> body(dof_handler.get_triangulation().n_active_cells());
      for (const auto &cell : dof_handler.active_cell_iterators())
        body(cell->active_cell_index()) = cell->material_id();
      data_out.add_data_vector(body, "body");

      // Fast zlib compression: the default (best compression) costs as much
      // as the solve on production meshes for a few percent of file size.
      DataOutBase::VtkFlags flags;
      flags.compression_level = DataOutBase::VtkFlags::best_speed;
      data_out.set_flags(flags);

      const unsigned int degree = fe.degree;
      data_out.build_patches(mapping, degree, DataOut<dim>::curved_inner_cells);
      const std::string pvtu =
        data_out.write_vtu_with_pvtu_record(parameters.directory + "/",
                                            base_name,
                                            step,
                                            mpi_communicator,
                                            4,
                                            0);

      records.emplace_back(time, pvtu);
      if (Utilities::MPI::this_mpi_process(mpi_communicator) == 0)
        {
          std::ofstream pvd(parameters.path(base_name + ".pvd"));
          DataOutBase::write_pvd_record(pvd, records);
        }
    }

    template class SolutionOutput<2>;
    template class SolutionOutput<3>;
  } // namespace IO
} // namespace Common
