#include <common/physics/boundary_loads.h>

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/vector.h>

#include <vector>

namespace Common
{
  namespace Physics
  {
    using namespace dealii;

    template <int dim>
    void
    add_boundary_pressure(const Mapping<dim>              &mapping,
                          const DoFHandler<dim>           &dof_handler,
                          const types::boundary_id         boundary_id,
                          const double                     pressure,
                          const Kinematics                 kinematics,
                          const AffineConstraints<double> &constraints,
                          TrilinosWrappers::MPI::Vector   &rhs)
    {
      const FiniteElement<dim>            &fe = dof_handler.get_fe();
      const QGauss<dim - 1>                face_quadrature(fe.degree + 1);
      FEFaceValues<dim>                    fe_face_values(mapping,
                                       fe,
                                       face_quadrature,
                                       update_values | update_JxW_values |
                                         update_normal_vectors |
                                         update_quadrature_points);
      const unsigned int                   dofs_per_cell = fe.n_dofs_per_cell();
      Vector<double>                       cell_rhs(dofs_per_cell);
      std::vector<types::global_dof_index> dof_indices(dofs_per_cell);
      const FEValuesExtractors::Vector     displacement(0);

      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          for (const unsigned int f : cell->face_indices())
            if (cell->face(f)->at_boundary() &&
                cell->face(f)->boundary_id() == boundary_id)
              {
                fe_face_values.reinit(cell, f);
                cell_rhs = 0.;
                for (const unsigned int q :
                     fe_face_values.quadrature_point_indices())
                  {
                    const Tensor<1, dim> traction =
                      -pressure * fe_face_values.normal_vector(q);
                    const double JxW =
                      fe_face_values.JxW(q) *
                      measure_factor(kinematics,
                                     fe_face_values.quadrature_point(q));
                    for (unsigned int i = 0; i < dofs_per_cell; ++i)
                      cell_rhs(i) += fe_face_values[displacement].value(i, q) *
                                     traction * JxW;
                  }
                cell->get_dof_indices(dof_indices);
                constraints.distribute_local_to_global(cell_rhs,
                                                       dof_indices,
                                                       rhs);
              }
    }

    template void
    add_boundary_pressure(const Mapping<2> &,
                          const DoFHandler<2> &,
                          const types::boundary_id,
                          const double,
                          const Kinematics,
                          const AffineConstraints<double> &,
                          TrilinosWrappers::MPI::Vector &);
    template void
    add_boundary_pressure(const Mapping<3> &,
                          const DoFHandler<3> &,
                          const types::boundary_id,
                          const double,
                          const Kinematics,
                          const AffineConstraints<double> &,
                          TrilinosWrappers::MPI::Vector &);
  } // namespace Physics
} // namespace Common
