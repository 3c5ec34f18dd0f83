/**
 * @file finite_strain_solid.h
 * Bulk terms of a finite-strain solid in the total Lagrangian form (plane
 * strain, axisymmetric or 3D): internal forces
 * \f$f_i = \int_{\Omega_0}\tau : (\nabla_X N_i F^{-1})\,dV\f$ with the
 * Kirchhoff stress \f$\tau\f$ of a finite-strain law per material id, and
 * their exact linearisation (material and geometric parts), so that
 * Newton's method converges quadratically.
 *
 * Element technologies:
 * - displacement: the plain Q_k element;
 * - F-bar (Q1): the volumetric part of F replaced by that at the cell
 *   centre, \f$\bar F = (J_0/J)^{1/d}F\f$ (d = 2 in plane strain, else 3;
 *   de Souza Neto et al. 1996), against volumetric locking in nearly
 *   incompressible elasticity and isochoric plasticity;
 * - mixed: the three-field element \f$Q_k\f$-\f$P_{k-1}\f$-\f$P_{k-1}\f$
 *   (Q1-P0 mean dilatation, Q2-P1 with discontinuous pressure; Simo,
 *   Taylor and Pister 1985, deal.II step-44), with the dilatation
 *   \f$\tilde J = \Pi J\f$ and the pressure \f$\tilde p = \Pi U'(\tilde J)\f$
 *   condensed on each cell, for laws with a volumetric-isochoric split.
 *   An exactly incompressible law has no U: the element then enforces
 *   \f$\Pi J = 1\f$ by an augmented Lagrangian, \f$U'(\tilde J) = \lambda +
 *   \kappa(\tilde J - 1)\f$ with a multiplier field \f$\lambda\f$ per cell,
 *   updated by augment() after each converged Newton solve until
 *   \f$|\tilde J - 1|\f$ is below a tolerance; at that point the solution
 *   is the one of the mixed element with the pressure as a Lagrange
 *   multiplier.
 */
#ifndef common_physics_finite_strain_solid_h
#define common_physics_finite_strain_solid_h

#include <common/materials/finite_strain_material.h>
#include <common/physics/solid_operator.h>

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <boost/signals2/connection.hpp>

#include <map>
#include <memory>
#include <string>
#include <vector>

namespace Common
{
  namespace Physics
  {
    /** The element technology of a finite-strain solid. */
    enum class ElementTechnology
    {
      displacement,
      f_bar,
      mixed
    };

    /**
     * @brief The finite-strain entries of subsection "Solid": the element
     * technology and the augmented Lagrangian of exact incompressibility.
     */
    struct FiniteStrainParameters
    {
      /** @brief Declare "Element technology", "Incompressibility penalty
       * factor", "Incompressibility tolerance" and "Maximum augmentations"
       * in subsection "Solid". */
      static void
      declare_parameters(dealii::ParameterHandler &prm);

      /** @brief Read and check them. */
      void
      parse_parameters(dealii::ParameterHandler &prm);

      ElementTechnology technology = ElementTechnology::displacement;
      /** \f$\kappa/\mu\f$ of the augmented Lagrangian. */
      double penalty_factor = 1e3;
      /** Largest \f$|\tilde J - 1|\f$ that ends the augmentation. */
      double incompressibility_tolerance = 1e-8;
      /** Most multiplier updates in one load step. */
      unsigned int max_augmentations = 30;
    };

    /** @brief Check that @p technology exists for the element degree
     * @p degree (F-bar: Q1; mixed: Q1 or Q2); a one-line error names the
     * entry. */
    void
    check_element_technology(const ElementTechnology technology,
                             const unsigned int      degree);

    /** @brief Check that @p technology suits the law @p law of the body
     * named @p body (an exactly incompressible law needs the mixed
     * element, which needs a volumetric-isochoric split); a one-line
     * error names the body. */
    void
    check_element_technology(const ElementTechnology                technology,
                             const Materials::FiniteStrainMaterial &law,
                             const std::string                     &body);

    /**
     * @brief Total Lagrangian finite-strain solid on a vector-valued FE_Q
     * displacement space, with a finite-strain law per material id.
     *
     * The state of every quadrature point (plastic history) and the
     * multipliers of the incompressibility constraint are kept for the
     * locally owned cells: as committed with the last accepted step, and
     * as computed at the displacement of commit(). Assemblies read the
     * committed state only, so that a Newton iteration never changes it.
     */
    template <int dim>
    class FiniteStrainSolid : public SolidOperator<dim>
    {
    public:
      using typename SolidOperator<dim>::VectorType;
      using typename SolidOperator<dim>::MatrixType;

      /**
       * @param[in] mapping Geometry mapping of the reference configuration.
       * @param[in] fe Vector-valued FE_Q element with dim components.
       * @param[in] materials Law per material id; every cell's id must be
       * present. The laws must outlive this object.
       * @param[in] kinematics Plane strain/3D or axisymmetric (2D only).
       * @param[in] parameters Element technology and incompressibility.
       */
      FiniteStrainSolid(
        const dealii::Mapping<dim>                              &mapping,
        const dealii::FiniteElement<dim>                        &fe,
        const std::map<dealii::types::material_id,
                       const Materials::FiniteStrainMaterial *> &materials,
        const Kinematics                                         kinematics,
        const FiniteStrainParameters                            &parameters);

      /** @brief As above, with the laws owned by the solid. */
      FiniteStrainSolid(
        const dealii::Mapping<dim>       &mapping,
        const dealii::FiniteElement<dim> &fe,
        const std::map<dealii::types::material_id,
                       std::shared_ptr<const Materials::FiniteStrainMaterial>>
                                     &materials,
        const Kinematics              kinematics,
        const FiniteStrainParameters &parameters);

      /** @brief The kinematics of the model. */
      Kinematics
      kinematics() const override;

      /** @brief False: the residual is nonlinear. */
      bool
      is_linear() const override;

      /** @brief Tangent and residual \f$-f_{int}(u)\f$ on locally owned
       * cells, condensed with @p constraints; not compressed. */
      void
      assemble_system(const dealii::DoFHandler<dim>           &dof_handler,
                      const dealii::AffineConstraints<double> &constraints,
                      const VectorType                        &u,
                      MatrixType                              &matrix,
                      VectorType &residual) override;

      /** @brief assemble_system() and the terms @p bulk asks for, from one
       * integration of each cell; not compressed. */
      void
      assemble_system_and_bulk_terms(
        const dealii::DoFHandler<dim>                &dof_handler,
        const dealii::AffineConstraints<double>      &constraints,
        const VectorType                             &u,
        MatrixType                                   &matrix,
        VectorType                                   &residual,
        const typename SolidOperator<dim>::BulkTerms &bulk) override;

      /** @brief Internal forces \f$f_{int}(u)\f$ (N) on locally owned
       * cells, condensed with @p constraints; not compressed. */
      void
      assemble_internal_force(
        const dealii::DoFHandler<dim>           &dof_handler,
        const dealii::AffineConstraints<double> &constraints,
        const VectorType                        &u,
        VectorType                              &internal_force) override;

      /** @brief Keep the state at the converged displacement @p u. */
      void
      commit(const dealii::DoFHandler<dim> &dof_handler,
             const VectorType              &u) override;

      /** @brief Return to the last committed state. */
      void
      restore() override;

      /** @brief Forget every kept state (the triangulation changed). */
      void
      clear() override;

      /**
       * @brief Augmented Lagrangian update of exactly incompressible
       * cells at the converged displacement @p u:
       * \f$\lambda \leftarrow \lambda + \kappa(\tilde J - 1)\f$.
       * @return The largest \f$|\tilde J - 1|\f$ before the update over
       * all ranks (0 if no cell is exactly incompressible).
       */
      double
      augment(const dealii::DoFHandler<dim> &dof_handler, const VectorType &u);

      /** @brief augment() if the largest \f$|\tilde J - 1|\f$ exceeds
       * the incompressibility tolerance, and then true; otherwise the
       * multipliers stay as they are (the state is in equilibrium with
       * them) and false. */
      bool
      update_multipliers(const dealii::DoFHandler<dim> &dof_handler,
                         const VectorType              &u) override;

      /**
       * @brief The largest \f$|\tilde J - 1|\f$ of the exactly
       * incompressible cells at @p u over all ranks (0 if there are
       * none); with @p update, also the update of augment().
       */
      double
      dilatation_error(const dealii::DoFHandler<dim> &dof_handler,
                       const VectorType              &u,
                       const bool                     update);

      /** @brief "Maximum augmentations" if some cell is exactly
       * incompressible, else 0. */
      unsigned int
      max_multiplier_updates() const override;

      /** @brief The tolerance that ends augment() loops. */
      double
      incompressibility_tolerance() const;

      /** @brief True if some cell enforces exact incompressibility. */
      bool
      has_incompressibility_multipliers() const;

      /** @brief Cell averages of the Cauchy stress, von Mises stress,
       * equivalent plastic strain and J at the last commit(). */
      std::vector<std::unique_ptr<dealii::DataPostprocessor<dim>>>
      output_postprocessors() const override;

      /**
       * @brief Averages over a locally owned cell at the last commit():
       * Cauchy stress (MPa, 3x3), von Mises stress (MPa), equivalent
       * plastic strain, J, and the projected dilatation
       * \f$\tilde J\f$ (mixed element; else J).
       */
      struct CellAverages
      {
        dealii::SymmetricTensor<2, 3> cauchy_stress;
        double                        von_mises          = 0.;
        double                        plastic_strain     = 0.;
        double                        jacobian           = 1.;
        double                        projected_jacobian = 1.;
      };

      /** @brief The averages of the cell with active index @p index
       * (locally owned), at the last commit(). */
      const CellAverages &
      cell_averages(const unsigned int active_cell_index) const;

      /** @brief The law of material id @p id. */
      const Materials::FiniteStrainMaterial &
      material(const dealii::types::material_id id) const;

    private:
      const dealii::Mapping<dim>       &mapping;
      const dealii::FiniteElement<dim> &fe;
      /** Laws the solid owns (second constructor). */
      std::vector<std::shared_ptr<const Materials::FiniteStrainMaterial>>
        owned_materials;
      const std::map<dealii::types::material_id,
                     const Materials::FiniteStrainMaterial *>
                                   materials;
      const Kinematics             model_kinematics;
      const FiniteStrainParameters parameters;
      const dealii::QGauss<dim>    quadrature;
      /** Number of pressure (and dilatation) functions per cell. */
      const unsigned int n_pressure;

      /** Index of each locally owned cell into the kept states, by
       * active cell index (invalid for other cells). */
      std::vector<unsigned int> owned_index;
      /** Quadrature point states and multipliers: committed, and as
       * computed by commit() before it copies them. */
      std::vector<Materials::MaterialPointState> committed_states;
      /** Multipliers of the incompressibility constraint, n_pressure per
       * owned cell: current (augment() changes them during a step) and as
       * committed. */
      std::vector<double>                multipliers;
      std::vector<double>                committed_multipliers;
      std::vector<CellAverages>          averages;
      const dealii::DoFHandler<dim>     *cached_dof_handler = nullptr;
      boost::signals2::scoped_connection triangulation_changed;

      /** Allocate the kept states for @p dof_handler's owned cells unless
       * they exist. */
      void
      ensure_storage(const dealii::DoFHandler<dim> &dof_handler);

      /** What integrate_cell() computes. */
      struct CellOutput
      {
        dealii::FullMatrix<double>                 *matrix   = nullptr;
        dealii::Vector<double>                     *force    = nullptr;
        std::vector<Materials::MaterialPointState> *states   = nullptr;
        CellAverages                               *averages = nullptr;
        /** Projected dilatation coefficients (mixed element). */
        dealii::Vector<double> *dilatation = nullptr;
        /** Largest |projected J - 1| at the quadrature points (mixed
         * element). */
        double *dilatation_error = nullptr;
      };

      /** FEValues objects and per-DoF work arrays. */
      struct Scratch;

      /** Internal force, tangent, updated states and averages of one
       * cell at the displacement @p u_cell, as far as @p output asks. */
      void
      integrate_cell(
        const typename dealii::DoFHandler<dim>::active_cell_iterator &cell,
        const dealii::Vector<double>                                 &u_cell,
        Scratch                                                      &scratch,
        CellOutput &output) const;

      /** Internal forces into @p vector (no @p matrix), or the tangent and
       * the residual -f_int (with @p matrix), condensed; and the terms
       * @p bulk asks for from the same cell integrals. */
      void
      assemble(const dealii::DoFHandler<dim>                &dof_handler,
               const dealii::AffineConstraints<double>      &constraints,
               const VectorType                             &u,
               MatrixType                                   *matrix,
               VectorType                                   &vector,
               const typename SolidOperator<dim>::BulkTerms &bulk = {});

      /** Run @p work(cell, u_cell, dof_indices, scratch) on every locally
       * owned cell. */
      template <typename Work>
      void
      for_owned_cells(const dealii::DoFHandler<dim> &dof_handler,
                      const VectorType              &u,
                      const Work                    &work);
    };
  } // namespace Physics
} // namespace Common

#endif
