#include <common/physics/small_strain_elasticity.h>

#include <deal.II/base/numbers.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/fe_values_extractors.h>

namespace Common
{
  namespace Physics
  {
    using namespace dealii;

    template <int dim>
    SmallStrainElasticity<dim>::SmallStrainElasticity(
      const Mapping<dim>       &mapping,
      const FiniteElement<dim> &fe,
      const std::map<types::material_id, Materials::LinearElastic<dim>>
                      &materials,
      const Kinematics kinematics)
      : mapping(mapping)
      , fe(fe)
      , materials(materials)
      , model_kinematics(kinematics)
      , quadrature(fe.degree + 1)
    {
      AssertThrow(dim == 2 || kinematics == Kinematics::cartesian,
                  ExcMessage("Axisymmetric kinematics needs a 2D model."));
    }



    template <int dim>
    Kinematics
    SmallStrainElasticity<dim>::kinematics() const
    {
      return model_kinematics;
    }



    template <int dim>
    bool
    SmallStrainElasticity<dim>::is_linear() const
    {
      return true;
    }



    template <int dim>
    std::vector<std::unique_ptr<DataPostprocessor<dim>>>
    SmallStrainElasticity<dim>::output_postprocessors() const
    {
      std::vector<std::unique_ptr<DataPostprocessor<dim>>> postprocessors;
      postprocessors.push_back(
        std::make_unique<StressPostprocessor<dim>>(*this));
      return postprocessors;
    }



    template <int dim>
    const Materials::LinearElastic<dim> &
    SmallStrainElasticity<dim>::material(const types::material_id id) const
    {
      const auto it = materials.find(id);
      AssertThrow(it != materials.end(),
                  ExcMessage("No material for material id " +
                             std::to_string(id) + "."));
      return it->second;
    }



    template <int dim>
    void
    SmallStrainElasticity<dim>::clear()
    {
      cell_matrices.clear();
      cached_dof_handler = nullptr;
      cached_n_dofs      = 0;
    }



    template <int dim>
    void
    SmallStrainElasticity<dim>::ensure_cell_matrices(
      const DoFHandler<dim> &dof_handler)
    {
      if (cached_dof_handler == &dof_handler &&
          cached_n_dofs == dof_handler.n_dofs() &&
          cell_matrices.size() ==
            dof_handler.get_triangulation().n_active_cells())
        return;
      // Any change of the triangulation (refinement, coarsening, moved
      // vertices) invalidates the matrices, whatever the cell count.
      triangulation_changed =
        dof_handler.get_triangulation().signals.any_change.connect(
          [this]() { clear(); });
      cached_dof_handler = &dof_handler;
      cached_n_dofs      = dof_handler.n_dofs();

      const unsigned int dofs_per_cell = fe.n_dofs_per_cell();
      cell_matrices.assign(dof_handler.get_triangulation().n_active_cells(),
                           FullMatrix<double>());

      const bool    axisymmetric = model_kinematics == Kinematics::axisymmetric;
      FEValues<dim> fe_values(mapping,
                              fe,
                              quadrature,
                              update_values | update_gradients |
                                update_JxW_values | update_quadrature_points);
      const FEValuesExtractors::Vector     displacement(0);
      std::vector<SymmetricTensor<2, dim>> sym_grad(dofs_per_cell);
      // Hoop strain u_r/r of each shape function (axisymmetric only).
      std::vector<double> hoop(dofs_per_cell, 0.);

      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            fe_values.reinit(cell);
            const auto         &law    = material(cell->material_id());
            const auto         &C      = law.tangent();
            const double        lambda = law.lame_lambda(), mu = law.lame_mu();
            FullMatrix<double> &K = cell_matrices[cell->active_cell_index()];
            K.reinit(dofs_per_cell, dofs_per_cell);
            for (const unsigned int q : fe_values.quadrature_point_indices())
              {
                const Point<dim> &x = fe_values.quadrature_point(q);
                for (unsigned int i = 0; i < dofs_per_cell; ++i)
                  {
                    sym_grad[i] =
                      fe_values[displacement].symmetric_gradient(i, q);
                    if (axisymmetric)
                      hoop[i] = fe_values[displacement].value(i, q)[0] / x[0];
                  }
                const double JxW =
                  fe_values.JxW(q) * measure_factor(model_kinematics, x);
                for (unsigned int i = 0; i < dofs_per_cell; ++i)
                  {
                    const SymmetricTensor<2, dim> C_eps_i = C * sym_grad[i];
                    // With the hoop strain: sigma_i : eps_j gains
                    // lambda (tr_i e_j + e_i tr_j + e_i e_j) + 2 mu e_i e_j,
                    // tr the in-plane trace and e the hoop strain.
                    const double tr_i = trace(sym_grad[i]);
                    for (unsigned int j = 0; j <= i; ++j)
                      {
                        double value = C_eps_i * sym_grad[j];
                        if (axisymmetric)
                          value += lambda * (tr_i * hoop[j] +
                                             hoop[i] * trace(sym_grad[j])) +
                                   (lambda + 2. * mu) * hoop[i] * hoop[j];
                        K(i, j) += value * JxW;
                      }
                  }
              }
            for (unsigned int i = 0; i < dofs_per_cell; ++i)
              for (unsigned int j = i + 1; j < dofs_per_cell; ++j)
                K(i, j) = K(j, i);
          }
    }



    template <int dim>
    void
    SmallStrainElasticity<dim>::assemble_system(
      const DoFHandler<dim>           &dof_handler,
      const AffineConstraints<double> &constraints,
      const VectorType                &u,
      MatrixType                      &matrix,
      VectorType                      &residual)
    {
      ensure_cell_matrices(dof_handler);

      const unsigned int                   dofs_per_cell = fe.n_dofs_per_cell();
      std::vector<types::global_dof_index> dof_indices(dofs_per_cell);
      Vector<double>                       u_cell(dofs_per_cell);
      Vector<double>                       r_cell(dofs_per_cell);

      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            cell->get_dof_indices(dof_indices);
            for (unsigned int i = 0; i < dofs_per_cell; ++i)
              u_cell(i) = u(dof_indices[i]);
            const FullMatrix<double> &K =
              cell_matrices[cell->active_cell_index()];
            K.vmult(r_cell, u_cell);
            r_cell *= -1.;
            constraints.distribute_local_to_global(K,
                                                   r_cell,
                                                   dof_indices,
                                                   matrix,
                                                   residual);
          }
    }



    template <int dim>
    void
    SmallStrainElasticity<dim>::assemble_internal_force(
      const DoFHandler<dim>           &dof_handler,
      const AffineConstraints<double> &constraints,
      const VectorType                &u,
      VectorType                      &internal_force)
    {
      ensure_cell_matrices(dof_handler);

      const unsigned int                   dofs_per_cell = fe.n_dofs_per_cell();
      std::vector<types::global_dof_index> dof_indices(dofs_per_cell);
      Vector<double>                       u_cell(dofs_per_cell);
      Vector<double>                       f_cell(dofs_per_cell);

      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            cell->get_dof_indices(dof_indices);
            for (unsigned int i = 0; i < dofs_per_cell; ++i)
              u_cell(i) = u(dof_indices[i]);
            cell_matrices[cell->active_cell_index()].vmult(f_cell, u_cell);
            constraints.distribute_local_to_global(f_cell,
                                                   dof_indices,
                                                   internal_force);
          }
    }



    template <int dim>
    StressPostprocessor<dim>::StressPostprocessor(
      const SmallStrainElasticity<dim> &physics)
      : DataPostprocessorTensor<dim>("stress",
                                     update_values | update_gradients |
                                       update_quadrature_points)
      , physics(physics)
    {}



    template <int dim>
    void
    StressPostprocessor<dim>::evaluate_vector_field(
      const DataPostprocessorInputs::Vector<dim> &inputs,
      std::vector<Vector<double>>                &computed_quantities) const
    {
      const auto  cell = inputs.template get_cell<dim>();
      const auto &law  = physics.material(cell->material_id());
      for (unsigned int q = 0; q < inputs.solution_gradients.size(); ++q)
        {
          Tensor<2, dim> grad;
          for (unsigned int d = 0; d < dim; ++d)
            grad[d] = inputs.solution_gradients[q][d];
          SymmetricTensor<2, dim> sigma = law.stress(symmetrize(grad));
          if (physics.kinematics() == Kinematics::axisymmetric)
            {
              // Hoop strain u_r/r, and its limit du_r/dr on the axis.
              const double r = inputs.evaluation_points[q][0];
              const double hoop =
                (r > 1e-12 ? inputs.solution_values[q][0] / r : grad[0][0]);
              for (unsigned int d = 0; d < dim; ++d)
                sigma[d][d] += law.lame_lambda() * hoop;
            }
          for (unsigned int d = 0; d < dim; ++d)
            for (unsigned int e = 0; e < dim; ++e)
              computed_quantities[q](
                Tensor<2, dim>::component_to_unrolled_index(
                  TableIndices<2>(d, e))) = sigma[d][e];
        }
    }

    template class SmallStrainElasticity<2>;
    template class SmallStrainElasticity<3>;
    template class StressPostprocessor<2>;
    template class StressPostprocessor<3>;
  } // namespace Physics
} // namespace Common
