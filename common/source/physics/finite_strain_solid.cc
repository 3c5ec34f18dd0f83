#include <common/io/console.h>
#include <common/physics/finite_strain_solid.h>

#include <deal.II/base/mpi.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/numerics/data_component_interpretation.h>

#include <cmath>
#include <limits>

namespace Common
{
  namespace Physics
  {
    using namespace dealii;

    namespace
    {
      Tensor<2, 3>
      identity3()
      {
        return unit_symmetric_tensor<3>();
      }



      /**
       * Cell averages for graphical output: the Cauchy stress, von Mises
       * stress, equivalent plastic strain and J of each locally owned cell
       * at the last commit (constant over the cell).
       */
      template <int dim>
      class FiniteStrainPostprocessor : public DataPostprocessor<dim>
      {
      public:
        explicit FiniteStrainPostprocessor(const FiniteStrainSolid<dim> &solid)
          : solid(solid)
        {}

        void
        evaluate_vector_field(
          const DataPostprocessorInputs::Vector<dim> &inputs,
          std::vector<Vector<double>> &computed_quantities) const override
        {
          const auto  cell = inputs.template get_cell<dim>();
          const auto &a    = solid.cell_averages(cell->active_cell_index());
          for (auto &values : computed_quantities)
            {
              for (unsigned int d = 0; d < dim; ++d)
                for (unsigned int e = 0; e < dim; ++e)
                  values(d * dim + e) = a.cauchy_stress[d][e];
              values(dim * dim)     = a.von_mises;
              values(dim * dim + 1) = a.plastic_strain;
              values(dim * dim + 2) = a.jacobian;
            }
        }

        std::vector<std::string>
        get_names() const override
        {
          std::vector<std::string> names(dim * dim, "cauchy_stress");
          names.emplace_back("von_mises_stress");
          names.emplace_back("equivalent_plastic_strain");
          names.emplace_back("J");
          return names;
        }

        std::vector<DataComponentInterpretation::DataComponentInterpretation>
        get_data_component_interpretation() const override
        {
          std::vector<DataComponentInterpretation::DataComponentInterpretation>
            interpretation(
              dim * dim,
              DataComponentInterpretation::component_is_part_of_tensor);
          interpretation.resize(
            dim * dim + 3,
            DataComponentInterpretation::component_is_scalar);
          return interpretation;
        }

        UpdateFlags
        get_needed_update_flags() const override
        {
          return update_values;
        }

      private:
        const FiniteStrainSolid<dim> &solid;
      };
    } // namespace



    void
    FiniteStrainParameters::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Solid");
      {
        prm.declare_entry(
          "Element technology",
          "displacement",
          Patterns::Selection("displacement|F-bar|mixed"),
          "Element of the finite-strain solid: displacement: plain Q_k; "
          "F-bar: Q1 with the volumetric deformation of the cell centre "
          "(against locking in nearly incompressible elasticity and in "
          "plasticity); mixed: Q_k-P_(k-1)-P_(k-1) with the dilatation and "
          "pressure condensed on each cell (Q1-P0, Q2-P1), for laws with a "
          "volumetric-isochoric split, required for exact "
          "incompressibility.");
        prm.declare_entry(
          "Incompressibility penalty factor",
          "1000",
          Patterns::Double(),
          "Exactly incompressible laws: the penalty kappa of the augmented "
          "Lagrangian as a multiple of the shear modulus. Dimensionless, "
          "positive and at most 1e6; it changes the number of "
          "augmentations, not the converged answer. Larger factors put the "
          "round-off of the penalty term (about the factor times 1e-16, "
          "relative) near the Newton tolerance: the coarse rolling case "
          "converges up to 1e7 and not at 1e8.");
        prm.declare_entry(
          "Incompressibility tolerance",
          "1e-8",
          Patterns::Double(),
          "Exactly incompressible laws: the augmentation ends when the "
          "projected J differs from 1 by less than this at every "
          "quadrature point. Dimensionless, positive.");
        prm.declare_entry(
          "Maximum augmentations",
          "30",
          Patterns::Integer(1),
          "Exactly incompressible laws: the most multiplier updates (each "
          "followed by a Newton solve) in one load step; a step that still "
          "violates the tolerance after them is cut back. Positive "
          "integer.");
      }
      prm.leave_subsection();
    }



    void
    FiniteStrainParameters::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Solid");
      {
        const std::string name = prm.get("Element technology");
        technology             = name == "F-bar" ? ElementTechnology::f_bar :
                                 name == "mixed" ? ElementTechnology::mixed :
                                                   ElementTechnology::displacement;
        penalty_factor = prm.get_double("Incompressibility penalty factor");
        incompressibility_tolerance =
          prm.get_double("Incompressibility tolerance");
        max_augmentations = prm.get_integer("Maximum augmentations");
      }
      prm.leave_subsection();
      AssertThrow(penalty_factor > 0. && penalty_factor <= 1e6,
                  ExcMessage("Solid: 'Incompressibility penalty factor' "
                             "must be positive and at most 1e6, got " +
                             IO::Console::format(penalty_factor) + "."));
      AssertThrow(incompressibility_tolerance > 0.,
                  ExcMessage("Solid: 'Incompressibility tolerance' must "
                             "be positive."));
    }



    template <int dim>
    struct FiniteStrainSolid<dim>::Scratch
    {
      Scratch(const Mapping<dim>       &mapping,
              const FiniteElement<dim> &fe,
              const Quadrature<dim>    &quadrature)
        : fe_values(mapping,
                    fe,
                    quadrature,
                    update_values | update_gradients | update_JxW_values |
                      update_quadrature_points)
        , fe_center(mapping,
                    fe,
                    QGauss<dim>(1),
                    update_values | update_gradients | update_quadrature_points)
        , G(fe.n_dofs_per_cell())
        , g(fe.n_dofs_per_cell())
        , G0(fe.n_dofs_per_cell())
        , DG(fe.n_dofs_per_cell())
        , T(fe.n_dofs_per_cell())
        , trace_g(fe.n_dofs_per_cell())
        , trace_h0(fe.n_dofs_per_cell(), 0.)
        , tau_g(fe.n_dofs_per_cell())
      {}

      FEValues<dim>             fe_values;
      FEValues<dim>             fe_center;
      std::vector<Tensor<2, 3>> G, g, G0, DG, T;
      std::vector<double>       trace_g, trace_h0, tau_g;
    };



    void
    check_element_technology(const ElementTechnology technology,
                             const unsigned int      degree)
    {
      AssertThrow(technology != ElementTechnology::f_bar || degree == 1,
                  ExcMessage("Solid: 'Element technology = F-bar' is a Q1 "
                             "element; use element degree 1 or the mixed "
                             "element."));
      AssertThrow(technology != ElementTechnology::mixed || degree <= 2,
                  ExcMessage("Solid: the mixed element is Q1-P0 or Q2-P1; "
                             "use element degree 1 or 2."));
    }



    void
    check_element_technology(const ElementTechnology                technology,
                             const Materials::FiniteStrainMaterial &law,
                             const std::string                     &body)
    {
      AssertThrow(technology == ElementTechnology::mixed ||
                    !law.is_incompressible(),
                  ExcMessage(body + ": Poisson's ratio 0.5 (exactly "
                                    "incompressible) needs 'Element technology "
                                    "= mixed' in subsection Solid."));
      AssertThrow(technology != ElementTechnology::mixed ||
                    law.has_volumetric_split(),
                  ExcMessage(body + ": the mixed element needs a law with a "
                                    "volumetric-isochoric split ('neo-Hookean "
                                    "split' or 'J2 plasticity')."));
    }



    template <int dim>
    FiniteStrainSolid<dim>::FiniteStrainSolid(
      const Mapping<dim>                                      &mapping,
      const FiniteElement<dim>                                &fe,
      const std::map<types::material_id,
                     const Materials::FiniteStrainMaterial *> &materials,
      const Kinematics                                         kinematics,
      const FiniteStrainParameters                            &parameters)
      : mapping(mapping)
      , fe(fe)
      , materials(materials)
      , model_kinematics(kinematics)
      , parameters(parameters)
      , quadrature(fe.degree + 1)
      , n_pressure(fe.degree == 1 ? 1 : dim + 1)
    {
      AssertThrow(dim == 2 || kinematics == Kinematics::cartesian,
                  ExcMessage("Axisymmetric kinematics needs a 2D model."));
      check_element_technology(parameters.technology, fe.degree);
      for (const auto &[id, law] : materials)
        check_element_technology(parameters.technology,
                                 *law,
                                 "Material id " + std::to_string(id));
    }



    namespace
    {
      std::map<types::material_id, const Materials::FiniteStrainMaterial *>
      raw_pointers(
        const std::map<types::material_id,
                       std::shared_ptr<const Materials::FiniteStrainMaterial>>
          &materials)
      {
        std::map<types::material_id, const Materials::FiniteStrainMaterial *>
          pointers;
        for (const auto &[id, law] : materials)
          pointers[id] = law.get();
        return pointers;
      }
    } // namespace



    template <int dim>
    FiniteStrainSolid<dim>::FiniteStrainSolid(
      const Mapping<dim>       &mapping,
      const FiniteElement<dim> &fe,
      const std::map<types::material_id,
                     std::shared_ptr<const Materials::FiniteStrainMaterial>>
                                   &materials,
      const Kinematics              kinematics,
      const FiniteStrainParameters &parameters)
      : FiniteStrainSolid(mapping,
                          fe,
                          raw_pointers(materials),
                          kinematics,
                          parameters)
    {
      for (const auto &[id, law] : materials)
        owned_materials.push_back(law);
    }



    template <int dim>
    Kinematics
    FiniteStrainSolid<dim>::kinematics() const
    {
      return model_kinematics;
    }



    template <int dim>
    bool
    FiniteStrainSolid<dim>::is_linear() const
    {
      return false;
    }



    template <int dim>
    const Materials::FiniteStrainMaterial &
    FiniteStrainSolid<dim>::material(const types::material_id id) const
    {
      const auto it = materials.find(id);
      AssertThrow(it != materials.end(),
                  ExcMessage("No material for material id " +
                             std::to_string(id) + "."));
      return *it->second;
    }



    template <int dim>
    void
    FiniteStrainSolid<dim>::clear()
    {
      owned_index.clear();
      committed_states.clear();
      multipliers.clear();
      committed_multipliers.clear();
      averages.clear();
      cached_dof_handler = nullptr;
    }



    template <int dim>
    void
    FiniteStrainSolid<dim>::ensure_storage(const DoFHandler<dim> &dof_handler)
    {
      const auto &triangulation = dof_handler.get_triangulation();
      if (cached_dof_handler == &dof_handler &&
          owned_index.size() == triangulation.n_active_cells())
        return;
      triangulation_changed =
        triangulation.signals.any_change.connect([this]() { clear(); });
      cached_dof_handler = &dof_handler;
      owned_index.assign(triangulation.n_active_cells(),
                         numbers::invalid_unsigned_int);
      unsigned int n_owned = 0;
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          owned_index[cell->active_cell_index()] = n_owned++;
      committed_states.assign(n_owned * quadrature.size(),
                              Materials::MaterialPointState());
      multipliers.assign(n_owned * n_pressure, 0.);
      committed_multipliers = multipliers;
      averages.assign(n_owned, CellAverages());
    }



    template <int dim>
    template <typename Work>
    void
    FiniteStrainSolid<dim>::for_owned_cells(const DoFHandler<dim> &dof_handler,
                                            const VectorType      &u,
                                            const Work            &work)
    {
      ensure_storage(dof_handler);
      Scratch                              scratch(mapping, fe, quadrature);
      const unsigned int                   n = fe.n_dofs_per_cell();
      std::vector<types::global_dof_index> dof_indices(n);
      Vector<double>                       u_cell(n);
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            cell->get_dof_indices(dof_indices);
            for (unsigned int i = 0; i < n; ++i)
              u_cell(i) = u(dof_indices[i]);
            work(cell, u_cell, dof_indices, scratch);
          }
    }



    template <int dim>
    void
    FiniteStrainSolid<dim>::integrate_cell(
      const typename DoFHandler<dim>::active_cell_iterator &cell,
      const Vector<double>                                 &u_cell,
      Scratch                                              &scratch,
      CellOutput                                           &output) const
    {
      const unsigned int n    = fe.n_dofs_per_cell();
      const unsigned int nq   = quadrature.size();
      const unsigned int np   = n_pressure;
      const auto        &law  = material(cell->material_id());
      const bool axisymmetric = model_kinematics == Kinematics::axisymmetric;
      const bool plane_strain = dim == 2 && !axisymmetric;
      const auto technology   = parameters.technology;
      const bool mixed        = technology == ElementTechnology::mixed;
      const bool f_bar        = technology == ElementTechnology::f_bar;
      const unsigned int cell_index = owned_index[cell->active_cell_index()];
      const Materials::MaterialPointState *states =
        &committed_states[cell_index * nq];

      // F and dF/du_i (G_i) at point q of fe_values (the hoop stretch
      // 1 + u_r/R in the 33 entry for axisymmetry, 1 in plane strain).
      const auto kinematics_at = [&](const FEValues<dim>       &fv,
                                     const unsigned int         q,
                                     std::vector<Tensor<2, 3>> &G) {
        Tensor<2, 3>      F = identity3();
        const Point<dim> &X = fv.quadrature_point(q);
        for (unsigned int i = 0; i < n; ++i)
          {
            const unsigned int c    = fe.system_to_component_index(i).first;
            const auto         grad = fv.shape_grad(i, q);
            G[i]                    = Tensor<2, 3>();
            for (unsigned int d = 0; d < dim; ++d)
              G[i][c][d] = grad[d];
            if (axisymmetric && c == 0)
              G[i][2][2] = fv.shape_value(i, q) / X[0];
            F += u_cell(i) * G[i];
          }
        return F;
      };

      scratch.fe_values.reinit(cell);
      auto &fv = scratch.fe_values;

      // F-bar: the deformation at the cell centre.
      double J0 = 1.;
      if (f_bar)
        {
          scratch.fe_center.reinit(cell);
          const Tensor<2, 3> F0 =
            kinematics_at(scratch.fe_center, 0, scratch.G0);
          const Tensor<2, 3> F0_inverse = invert(F0);
          J0                            = determinant(F0);
          for (unsigned int i = 0; i < n; ++i)
            scratch.trace_h0[i] = trace(scratch.G0[i] * F0_inverse);
        }

      // Mixed element: the projected dilatation and pressure of the cell,
      // and the condensed volumetric stiffness B^T M^-1 M_U M^-1 B.
      Vector<double>              pressure(np), dilatation(np);
      FullMatrix<double>          volumetric_stiffness;
      std::vector<Vector<double>> psi(nq, Vector<double>(np));
      if (mixed)
        {
          const Point<dim>    centre = cell->center();
          const double        h      = cell->diameter();
          FullMatrix<double>  M(np, np), B(np, n), M_inverse(np, np);
          Vector<double>      integral_J(np);
          std::vector<double> dV(nq);
          for (unsigned int q = 0; q < nq; ++q)
            {
              const Tensor<2, 3> F         = kinematics_at(fv, q, scratch.G);
              const Tensor<2, 3> F_inverse = invert(F);
              const double       J         = determinant(F);
              const Point<dim>  &X         = fv.quadrature_point(q);
              dV[q]     = fv.JxW(q) * measure_factor(model_kinematics, X);
              psi[q](0) = 1.;
              for (unsigned int d = 0; d + 1 < np; ++d)
                psi[q](d + 1) = (X[d] - centre[d]) / h;
              for (unsigned int k = 0; k < np; ++k)
                {
                  integral_J(k) += psi[q](k) * J * dV[q];
                  for (unsigned int l = 0; l < np; ++l)
                    M(k, l) += psi[q](k) * psi[q](l) * dV[q];
                  for (unsigned int i = 0; i < n; ++i)
                    B(k, i) +=
                      psi[q](k) * J * trace(scratch.G[i] * F_inverse) * dV[q];
                }
            }
          M_inverse.invert(M);
          M_inverse.vmult(dilatation, integral_J);
          FullMatrix<double> M_U(np, np);
          if (law.is_incompressible())
            {
              const double kappa =
                parameters.penalty_factor * law.shear_modulus();
              for (unsigned int k = 0; k < np; ++k)
                pressure(k) = multipliers[cell_index * np + k] +
                              kappa * (dilatation(k) - (k == 0 ? 1. : 0.));
              M_U = M;
              M_U *= kappa;
            }
          else
            {
              Vector<double> integral_p(np);
              for (unsigned int q = 0; q < nq; ++q)
                {
                  const auto [dU, d2U] =
                    law.volumetric_response(psi[q] * dilatation);
                  for (unsigned int k = 0; k < np; ++k)
                    {
                      integral_p(k) += psi[q](k) * dU * dV[q];
                      for (unsigned int l = 0; l < np; ++l)
                        M_U(k, l) += psi[q](k) * d2U * psi[q](l) * dV[q];
                    }
                }
              M_inverse.vmult(pressure, integral_p);
            }
          if (output.dilatation != nullptr)
            *output.dilatation = dilatation;
          if (output.dilatation_error != nullptr)
            {
              *output.dilatation_error = 0.;
              for (unsigned int q = 0; q < nq; ++q)
                *output.dilatation_error =
                  std::max(*output.dilatation_error,
                           std::abs(psi[q] * dilatation - 1.));
            }
          if (output.matrix != nullptr)
            {
              FullMatrix<double> S(np, np), tmp(np, np), MB(np, n);
              M_inverse.mmult(tmp, M_U);
              tmp.mmult(S, M_inverse);
              S.mmult(MB, B);
              volumetric_stiffness.reinit(n, n);
              B.Tmmult(volumetric_stiffness, MB);
            }
        }

      if (output.matrix == nullptr && output.force == nullptr &&
          output.states == nullptr && output.averages == nullptr)
        return;

      if (output.matrix != nullptr)
        {
          output.matrix->reinit(n, n);
          if (mixed)
            *output.matrix = volumetric_stiffness;
        }
      if (output.force != nullptr)
        output.force->reinit(n);
      CellAverages sums;
      sums.jacobian = 0.;
      double volume = 0.;

      const double                    alpha = plane_strain ? 0.5 : 1. / 3.;
      Materials::FiniteStrainResponse response;
      for (unsigned int q = 0; q < nq; ++q)
        {
          const Tensor<2, 3> F         = kinematics_at(fv, q, scratch.G);
          const Tensor<2, 3> F_inverse = invert(F);
          const double       J         = determinant(F);
          const double       dV = fv.JxW(q) * measure_factor(model_kinematics,
                                                       fv.quadrature_point(q));
          for (unsigned int i = 0; i < n; ++i)
            {
              scratch.g[i]       = scratch.G[i] * F_inverse;
              scratch.trace_g[i] = trace(scratch.g[i]);
            }

          Materials::MaterialPointState  updated;
          Materials::MaterialPointState *updated_pointer =
            output.states != nullptr || output.averages != nullptr ? &updated :
                                                                     nullptr;
          // Without a matrix, the stress alone (no derivatives).
          const auto evaluate_law = [&](const Tensor<2, 3>         &F_law,
                                        const Materials::StressPart part) {
            if (output.matrix != nullptr)
              law.evaluate(F_law, states[q], part, response, updated_pointer);
            else
              law.evaluate_stress(F_law,
                                  states[q],
                                  part,
                                  response,
                                  updated_pointer);
          };
          // The stress evaluated, its factor r in the virtual work and the
          // deformation it was evaluated at.
          double       r = 1., c = 1.;
          Tensor<2, 3> F_active;
          if (f_bar)
            {
              c        = std::pow(J0 / J, alpha);
              r        = J / J0;
              F_active = F;
              if (plane_strain)
                F_active[2][2] = 0.;
              Tensor<2, 3> F_bar = c * F_active;
              if (plane_strain)
                F_bar[2][2] = 1.;
              evaluate_law(F_bar, Materials::StressPart::full);
            }
          else
            evaluate_law(F,
                         mixed ? Materials::StressPart::isochoric :
                                 Materials::StressPart::full);

          Tensor<2, 3> tau = response.kirchhoff_stress;
          double       p   = 0.;
          if (mixed)
            {
              p = psi[q] * pressure;
              tau += p * J * identity3();
            }

          if (output.force != nullptr)
            for (unsigned int i = 0; i < n; ++i)
              (*output.force)(i) += r * scalar_product(tau, scratch.g[i]) * dV;

          if (output.matrix != nullptr)
            {
              const Tensor<4, 3> &D = response.tangent;
              Tensor<2, 3>        D_F_active;
              if (f_bar)
                D_F_active = double_contract<2, 0, 3, 1>(D, F_active);
              for (unsigned int j = 0; j < n; ++j)
                {
                  scratch.DG[j] = double_contract<2, 0, 3, 1>(D, scratch.G[j]);
                  if (f_bar)
                    scratch.DG[j] =
                      c * (scratch.DG[j] +
                           alpha * (scratch.trace_h0[j] - scratch.trace_g[j]) *
                             D_F_active);
                  scratch.T[j]     = transpose(scratch.g[j]) * tau;
                  scratch.tau_g[j] = scalar_product(tau, scratch.g[j]);
                }
              for (unsigned int i = 0; i < n; ++i)
                for (unsigned int j = 0; j < n; ++j)
                  {
                    double value = scalar_product(scratch.DG[j], scratch.g[i]) -
                                   scalar_product(scratch.T[i], scratch.g[j]);
                    if (f_bar)
                      value += (scratch.trace_g[j] - scratch.trace_h0[j]) *
                               scratch.tau_g[i];
                    if (mixed)
                      value += p * J * scratch.trace_g[i] * scratch.trace_g[j];
                    (*output.matrix)(i, j) += r * value * dV;
                  }
            }

          if (output.states != nullptr)
            (*output.states)[q] = updated;
          if (output.averages != nullptr)
            {
              const SymmetricTensor<2, 3> sigma =
                symmetrize(tau) * (f_bar ? 1. / J0 : 1. / J);
              sums.cauchy_stress += sigma * dV;
              sums.von_mises += Materials::von_mises(sigma) * dV;
              sums.plastic_strain += updated.equivalent_plastic_strain * dV;
              sums.jacobian += J * dV;
              volume += dV;
            }
        }
      if (output.averages != nullptr)
        {
          CellAverages &a      = *output.averages;
          a.cauchy_stress      = sums.cauchy_stress / volume;
          a.von_mises          = sums.von_mises / volume;
          a.plastic_strain     = sums.plastic_strain / volume;
          a.jacobian           = sums.jacobian / volume;
          a.projected_jacobian = a.jacobian;
          if (mixed)
            for (unsigned int q = 0; q < nq; ++q)
              {
                const double Jq = psi[q] * dilatation;
                if (std::abs(Jq - 1.) > std::abs(a.projected_jacobian - 1.))
                  a.projected_jacobian = Jq;
              }
        }
    }



    template <int dim>
    void
    FiniteStrainSolid<dim>::assemble(
      const DoFHandler<dim>                        &dof_handler,
      const AffineConstraints<double>              &constraints,
      const VectorType                             &u,
      MatrixType                                   *matrix,
      VectorType                                   &vector,
      const typename SolidOperator<dim>::BulkTerms &bulk)
    {
      FullMatrix<double> K;
      Vector<double>     f;
      const bool         tangent = matrix != nullptr || bulk.tangent != nullptr;
      for_owned_cells(
        dof_handler,
        u,
        [&](const auto &cell,
            const auto &u_cell,
            const auto &dof_indices,
            Scratch    &scratch) {
          CellOutput output;
          output.matrix = tangent ? &K : nullptr;
          output.force  = &f;
          integrate_cell(cell, u_cell, scratch, output);
          if (bulk.tangent != nullptr)
            bulk.constraints->distribute_local_to_global(K,
                                                         dof_indices,
                                                         *bulk.tangent);
          if (bulk.internal_force != nullptr)
            bulk.constraints->distribute_local_to_global(f,
                                                         dof_indices,
                                                         *bulk.internal_force);
          if (matrix == nullptr)
            constraints.distribute_local_to_global(f, dof_indices, vector);
          else
            {
              f *= -1.;
              constraints.distribute_local_to_global(K,
                                                     f,
                                                     dof_indices,
                                                     *matrix,
                                                     vector);
            }
        });
    }



    template <int dim>
    void
    FiniteStrainSolid<dim>::assemble_system(
      const DoFHandler<dim>           &dof_handler,
      const AffineConstraints<double> &constraints,
      const VectorType                &u,
      MatrixType                      &matrix,
      VectorType                      &residual)
    {
      assemble(dof_handler, constraints, u, &matrix, residual);
    }



    template <int dim>
    void
    FiniteStrainSolid<dim>::assemble_system_and_bulk_terms(
      const DoFHandler<dim>                        &dof_handler,
      const AffineConstraints<double>              &constraints,
      const VectorType                             &u,
      MatrixType                                   &matrix,
      VectorType                                   &residual,
      const typename SolidOperator<dim>::BulkTerms &bulk)
    {
      assemble(dof_handler, constraints, u, &matrix, residual, bulk);
    }



    template <int dim>
    void
    FiniteStrainSolid<dim>::assemble_internal_force(
      const DoFHandler<dim>           &dof_handler,
      const AffineConstraints<double> &constraints,
      const VectorType                &u,
      VectorType                      &internal_force)
    {
      assemble(dof_handler, constraints, u, nullptr, internal_force);
    }



    template <int dim>
    void
    FiniteStrainSolid<dim>::commit(const DoFHandler<dim> &dof_handler,
                                   const VectorType      &u)
    {
      const unsigned int                         nq = quadrature.size();
      std::vector<Materials::MaterialPointState> updated(nq);
      for_owned_cells(dof_handler,
                      u,
                      [&](const auto &cell,
                          const auto &u_cell,
                          const auto &,
                          Scratch &scratch) {
                        const unsigned int index =
                          owned_index[cell->active_cell_index()];
                        CellOutput output;
                        output.states   = &updated;
                        output.averages = &averages[index];
                        integrate_cell(cell, u_cell, scratch, output);
                        std::copy(updated.begin(),
                                  updated.end(),
                                  committed_states.begin() + index * nq);
                      });
      committed_multipliers = multipliers;
    }



    template <int dim>
    void
    FiniteStrainSolid<dim>::restore()
    {
      multipliers = committed_multipliers;
    }



    template <int dim>
    double
    FiniteStrainSolid<dim>::augment(const DoFHandler<dim> &dof_handler,
                                    const VectorType      &u)
    {
      return dilatation_error(dof_handler, u, true);
    }



    template <int dim>
    double
    FiniteStrainSolid<dim>::dilatation_error(const DoFHandler<dim> &dof_handler,
                                             const VectorType      &u,
                                             const bool             update)
    {
      double largest = 0.;
      if (has_incompressibility_multipliers())
        {
          Vector<double> dilatation(n_pressure);
          for_owned_cells(dof_handler,
                          u,
                          [&](const auto &cell,
                              const auto &u_cell,
                              const auto &,
                              Scratch &scratch) {
                            const auto &law = material(cell->material_id());
                            if (!law.is_incompressible())
                              return;
                            double     error = 0.;
                            CellOutput output;
                            output.dilatation       = &dilatation;
                            output.dilatation_error = &error;
                            integrate_cell(cell, u_cell, scratch, output);
                            largest = std::max(largest, error);
                            if (!update)
                              return;
                            const double kappa =
                              parameters.penalty_factor * law.shear_modulus();
                            const unsigned int index =
                              owned_index[cell->active_cell_index()] *
                              n_pressure;
                            for (unsigned int k = 0; k < n_pressure; ++k)
                              multipliers[index + k] +=
                                kappa * (dilatation(k) - (k == 0 ? 1. : 0.));
                          });
        }
      return Utilities::MPI::max(largest, dof_handler.get_communicator());
    }



    template <int dim>
    bool
    FiniteStrainSolid<dim>::update_multipliers(
      const DoFHandler<dim> &dof_handler,
      const VectorType      &u)
    {
      // The multipliers change only if another solve follows: a state
      // accepted within the tolerance keeps the multipliers it is in
      // equilibrium with.
      if (dilatation_error(dof_handler, u, false) <=
          parameters.incompressibility_tolerance)
        return false;
      augment(dof_handler, u);
      return true;
    }



    template <int dim>
    unsigned int
    FiniteStrainSolid<dim>::max_multiplier_updates() const
    {
      return has_incompressibility_multipliers() ?
               parameters.max_augmentations :
               0;
    }



    template <int dim>
    double
    FiniteStrainSolid<dim>::incompressibility_tolerance() const
    {
      return parameters.incompressibility_tolerance;
    }



    template <int dim>
    bool
    FiniteStrainSolid<dim>::has_incompressibility_multipliers() const
    {
      if (parameters.technology != ElementTechnology::mixed)
        return false;
      for (const auto &[id, law] : materials)
        if (law->is_incompressible())
          return true;
      return false;
    }



    template <int dim>
    std::vector<std::unique_ptr<DataPostprocessor<dim>>>
    FiniteStrainSolid<dim>::output_postprocessors() const
    {
      std::vector<std::unique_ptr<DataPostprocessor<dim>>> postprocessors;
      postprocessors.push_back(
        std::make_unique<FiniteStrainPostprocessor<dim>>(*this));
      return postprocessors;
    }



    template <int dim>
    const typename FiniteStrainSolid<dim>::CellAverages &
    FiniteStrainSolid<dim>::cell_averages(const unsigned int index) const
    {
      static const CellAverages none;
      if (index >= owned_index.size() ||
          owned_index[index] == numbers::invalid_unsigned_int)
        return none;
      return averages[owned_index[index]];
    }

    template class FiniteStrainSolid<2>;
    template class FiniteStrainSolid<3>;
  } // namespace Physics
} // namespace Common
