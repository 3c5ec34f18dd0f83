/**
 * @file solid_operator.h
 * The bulk terms of a solid, as the contact-Newton problem sees them:
 * tangent and residual at a displacement, the internal forces, the state
 * of the material (committed with accepted load steps only), and the
 * fields it contributes to graphical output. Implemented by the
 * small-strain solid (plane strain, axisymmetric, 3D) and by any other
 * kinematics or material model; the problem class knows none of them.
 */
#ifndef common_physics_solid_operator_h
#define common_physics_solid_operator_h

#include <deal.II/base/point.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/numerics/data_postprocessor.h>

#include <memory>
#include <vector>

namespace Common
{
  namespace Physics
  {
    /** How the 2D coordinates are read. */
    enum class Kinematics
    {
      /** Plane strain in 2D; the solid itself in 3D. */
      cartesian,
      /** Axisymmetric (2D only): x = r, y = z, integrals per full ring. */
      axisymmetric
    };

    /**
     * @brief Factor from the 2D (or 3D) measure to the physical one at
     * point @p x: \f$2\pi x_0\f$ (mm) for axisymmetric kinematics, 1
     * otherwise. Multiply the JxW of volume and boundary integrals
     * (external loads included) by it.
     */
    template <int dim>
    double
    measure_factor(const Kinematics kinematics, const dealii::Point<dim> &x);

    /**
     * @brief Interface of the bulk terms of a solid on a vector-valued
     * FE_Q displacement space.
     *
     * Vectors are Trilinos vectors with ghost entries where they are read
     * (the displacement) and without where they are assembled; matrices
     * and vectors are not compressed by the operator, so that the caller
     * can add other terms first. Every constraint object acts on the
     * Newton increment.
     */
    template <int dim>
    class SolidOperator
    {
    public:
      using VectorType = dealii::TrilinosWrappers::MPI::Vector;
      using MatrixType = dealii::TrilinosWrappers::SparseMatrix;

      virtual ~SolidOperator() = default;

      /** @brief Plane strain/3D or axisymmetric: how surface and volume
       * integrals are measured. */
      virtual Kinematics
      kinematics() const = 0;

      /** @brief True if the residual is linear in the displacement and the
       * tangent constant: the caller may then keep a tangent it assembled
       * once. */
      virtual bool
      is_linear() const = 0;

      /**
       * @brief Assemble the tangent \f$K = \partial f_{int}/\partial u\f$
       * and the residual \f$r = -f_{int}(u)\f$ (N) on locally owned cells,
       * condensed with @p constraints.
       * @param[in] u Current displacement, ghosted (mm).
       */
      virtual void
      assemble_system(const dealii::DoFHandler<dim>           &dof_handler,
                      const dealii::AffineConstraints<double> &constraints,
                      const VectorType                        &u,
                      MatrixType                              &matrix,
                      VectorType                              &residual) = 0;

      /**
       * @brief The bulk terms a contact law reads beside the system: the
       * tangent and the internal force of the same cell integrals,
       * condensed with another constraint object than the system's.
       */
      struct BulkTerms
      {
        /** The constraints both terms are condensed with. */
        const dealii::AffineConstraints<double> *constraints = nullptr;
        /** The tangent \f$K\f$, or nullptr if not wanted. */
        MatrixType *tangent = nullptr;
        /** The internal force \f$f_{int}(u)\f$ (N), or nullptr if not
         * wanted. */
        VectorType *internal_force = nullptr;
      };

      /**
       * @brief assemble_system(), and in the same pass over the cells the
       * terms @p bulk asks for: each cell's integrals are computed once.
       * The default calls assemble_system() and assemble_internal_force()
       * as often as needed.
       */
      virtual void
      assemble_system_and_bulk_terms(
        const dealii::DoFHandler<dim>           &dof_handler,
        const dealii::AffineConstraints<double> &constraints,
        const VectorType                        &u,
        MatrixType                              &matrix,
        VectorType                              &residual,
        const BulkTerms                         &bulk);

      /**
       * @brief Internal force vector \f$f_{int}(u)\f$ (N) on locally owned
       * cells, condensed with @p constraints exactly as the residual of
       * assemble_system() (hanging-node forces moved to their parents,
       * constrained rows left zero).
       */
      virtual void
      assemble_internal_force(
        const dealii::DoFHandler<dim>           &dof_handler,
        const dealii::AffineConstraints<double> &constraints,
        const VectorType                        &u,
        VectorType                              &internal_force) = 0;

      /**
       * @brief Keep the material state at the converged displacement
       * @p u as the state of the last accepted load step (history
       * variables). Stateless materials do nothing.
       */
      virtual void
      commit(const dealii::DoFHandler<dim> &dof_handler, const VectorType &u);

      /** @brief Return to the material state of the last accepted load
       * step (before a cutback). */
      virtual void
      restore();

      /**
       * @brief After a converged solve at @p u, update the multipliers of
       * the constraints this solid enforces by an augmented Lagrangian
       * (exact incompressibility). Collective over the communicator of
       * @p dof_handler.
       * @return True if a constraint was violated beyond its tolerance, so
       * that the step must be solved again with the updated multipliers.
       * The default (no such constraints) returns false.
       */
      virtual bool
      update_multipliers(const dealii::DoFHandler<dim> &dof_handler,
                         const VectorType              &u);

      /** @brief Largest number of update_multipliers() calls that may
       * return true in one load step before the step counts as failed; 0
       * (the default) for a solid without multipliers. */
      virtual unsigned int
      max_multiplier_updates() const;

      /** @brief Forget every quantity kept between assemblies (after the
       * mesh or the DoFs changed, or to time a fresh assembly). */
      virtual void
      clear() = 0;

      /** @brief Postprocessors of the fields this solid adds to graphical
       * output (stress, strain, state variables); each refers to this
       * operator, which must outlive it. */
      virtual std::vector<std::unique_ptr<dealii::DataPostprocessor<dim>>>
      output_postprocessors() const = 0;
    };
  } // namespace Physics
} // namespace Common

#endif
