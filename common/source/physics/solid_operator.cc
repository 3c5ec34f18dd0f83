#include <common/physics/solid_operator.h>

#include <deal.II/base/numbers.h>

namespace Common
{
  namespace Physics
  {
    using namespace dealii;

    template <int dim>
    double
    measure_factor(const Kinematics kinematics, const Point<dim> &x)
    {
      return kinematics == Kinematics::axisymmetric ? 2. * numbers::PI * x[0] :
                                                      1.;
    }



    template <int dim>
    void
    SolidOperator<dim>::assemble_system_and_bulk_terms(
      const DoFHandler<dim>           &dof_handler,
      const AffineConstraints<double> &constraints,
      const VectorType                &u,
      MatrixType                      &matrix,
      VectorType                      &residual,
      const BulkTerms                 &bulk)
    {
      assemble_system(dof_handler, constraints, u, matrix, residual);
      if (bulk.tangent != nullptr)
        {
          VectorType unused(residual.locally_owned_elements(),
                            residual.get_mpi_communicator());
          assemble_system(dof_handler,
                          *bulk.constraints,
                          u,
                          *bulk.tangent,
                          unused);
        }
      if (bulk.internal_force != nullptr)
        assemble_internal_force(dof_handler,
                                *bulk.constraints,
                                u,
                                *bulk.internal_force);
    }



    template <int dim>
    void
    SolidOperator<dim>::commit(const DoFHandler<dim> &, const VectorType &)
    {}



    template <int dim>
    void
    SolidOperator<dim>::restore()
    {}



    template <int dim>
    bool
    SolidOperator<dim>::update_multipliers(const DoFHandler<dim> &,
                                           const VectorType &)
    {
      return false;
    }



    template <int dim>
    unsigned int
    SolidOperator<dim>::max_multiplier_updates() const
    {
      return 0;
    }

    template double
    measure_factor(const Kinematics, const Point<2> &);
    template double
    measure_factor(const Kinematics, const Point<3> &);
    template class SolidOperator<2>;
    template class SolidOperator<3>;
  } // namespace Physics
} // namespace Common
