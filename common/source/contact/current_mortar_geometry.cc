#include <common/contact/current_mortar_geometry.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/symmetric_tensor.h>

#include <algorithm>
#include <map>
#include <sstream>

namespace Common
{
  namespace Contact
  {
    using namespace dealii;

    namespace
    {
      /** The rotation about the axis a x b that takes the unit vector @p a
       * to the unit vector @p b (Rodrigues; the identity if they agree or
       * are opposite). */
      template <int dim>
      Tensor<2, dim>
      rotation_between(const Tensor<1, dim> &a, const Tensor<1, dim> &b)
      {
        Tensor<2, dim> Q    = unit_symmetric_tensor<dim>();
        const double   cosa = a * b;
        if (cosa <= -1. + 1e-12 || a.norm() == 0. || b.norm() == 0.)
          return Q;
        if constexpr (dim == 2)
          {
            const double sina = a[0] * b[1] - a[1] * b[0];
            Q[0][0]           = cosa;
            Q[0][1]           = -sina;
            Q[1][0]           = sina;
            Q[1][1]           = cosa;
          }
        else
          {
            const Tensor<1, dim> k = cross_product_3d(a, b);
            Tensor<2, dim>       K;
            K[0][1] = -k[2];
            K[0][2] = k[1];
            K[1][0] = k[2];
            K[1][2] = -k[0];
            K[2][0] = -k[1];
            K[2][1] = k[0];
            Q += K + K * K / (1. + cosa);
          }
        return Q;
      }
    } // namespace

    template <int dim>
    CurrentMortarGeometry<dim>::CurrentMortarGeometry(
      const DoFHandler<dim>   &dof_handler,
      const Mapping<dim>      &mapping,
      const types::boundary_id secondary_id,
      const types::boundary_id primary_id,
      const double             search_distance,
      const bool               axisymmetric)
      : dof_handler(dof_handler)
      , mapping(mapping)
      , secondary_id(secondary_id)
      , primary_id(primary_id)
      , search_distance(search_distance)
      , axisymmetric(axisymmetric)
    {}



    template <int dim>
    CurrentMortarGeometry<dim>::CurrentMortarGeometry(
      const DoFHandler<dim>             &dof_handler,
      const Mapping<dim>                &mapping,
      const types::boundary_id           secondary_id,
      const std::vector<RigidTool<dim>> &tools,
      const double                       search_distance,
      const bool                         axisymmetric)
      : dof_handler(dof_handler)
      , mapping(mapping)
      , secondary_id(secondary_id)
      , primary_id(numbers::invalid_boundary_id)
      , tools(tools)
      , search_distance(search_distance)
      , axisymmetric(axisymmetric)
      , angle(tools.size(), 0.)
      , accepted_angle(tools.size(), 0.)
    {
      AssertThrow(!tools.empty(),
                  ExcMessage("A contact pair needs a primary surface or at "
                             "least one rigid tool."));
      for (const auto &tool : tools)
        {
          AssertThrow(tool.surface != nullptr,
                      ExcMessage("Rigid tool '" + tool.name +
                                 "' has no surface."));
          for (const auto dof : tool.reference_node_dofs)
            AssertThrow(dof < dof_handler.n_dofs(),
                        ExcMessage("The reference node of rigid tool '" +
                                   tool.name +
                                   "' needs a DoF for every component."));
          placed.push_back(std::make_unique<RigidSurface<dim>>(*tool.surface));
        }
    }



    template <int dim>
    void
    CurrentMortarGeometry<dim>::reinit(
      const AffineConstraints<double> &constraints,
      const RowSelector               &needed_rows)
    {
      this->constraints = &constraints;
      secondary         = std::make_unique<ContactSurface<dim>>(dof_handler,
                                                        mapping,
                                                        secondary_id);
      secondary->symmetrize_normals(constraints);
      node_faces.assign(secondary->n_nodes(), {});
      for (unsigned int f = 0; f < secondary->n_faces(); ++f)
        for (const unsigned int m : secondary->face(f).nodes)
          node_faces[m].push_back(f);
      integrated_rows =
        needed_rows ?
          MortarCoupling<dim>::rows_to_integrate(*secondary,
                                                 constraints,
                                                 needed_rows(*secondary)) :
          std::vector<bool>();
      if (tools.empty())
        {
          primary = std::make_unique<ContactSurface<dim>>(dof_handler,
                                                          mapping,
                                                          primary_id);
          // Its edges on symmetry planes (MortarCoupling's extension of
          // primary faces past them).
          primary->symmetrize_normals(constraints);
        }
      integrate(nullptr);
      pattern = current_pattern();
      accepted_normals.resize(mortar.n_rows());
      for (unsigned int j = 0; j < mortar.n_rows(); ++j)
        accepted_normals[j] = mortar.row(j).normal;
    }



    template <int dim>
    void
    CurrentMortarGeometry<dim>::integrate(const VectorType *u)
    {
      if (tools.empty())
        search = std::make_unique<ContactSearch<dim>>(*primary, 0.);
      else
        {
          partners.resize(tools.size());
          for (unsigned int i = 0; i < tools.size(); ++i)
            {
              Tensor<1, dim> translation;
              if (u != nullptr)
                for (unsigned int c = 0; c < dim; ++c)
                  translation[c] = (*u)(tools[i].reference_node_dofs[c]);
              placed[i]->set_placement(translation, angle[i], tools[i].centre);
              partners[i] = {placed[i].get(),
                             tools[i].reference_node_dofs,
                             translation};
            }
        }
      integrate_rows(*secondary,
                     primary.get(),
                     search.get(),
                     partners,
                     integrated_rows,
                     mortar);
    }



    template <int dim>
    void
    CurrentMortarGeometry<dim>::integrate_rows(
      const ContactSurface<dim>            &secondary_surface,
      const ContactSurface<dim>            *primary_surface,
      const ContactSearch<dim>             *primary_search,
      const std::vector<RigidPartner<dim>> &placed_tools,
      const std::vector<bool>              &rows,
      MortarCoupling<dim>                  &target) const
    {
      // Coincident edges of the two surfaces stay paired when an iterate
      // moves the primary edge inwards (MortarCoupling's free-edge
      // extension).
      target.set_free_edge_extension(0.05);
      // Rows integrated again at every iterate: the gap's own gradient.
      target.set_tool_normals(true);
      target.set_nodal_tool_gap(rigid_tool_gap == RigidToolGap::nodal);
      if (primary_surface != nullptr)
        target.reinit(secondary_surface,
                      *primary_surface,
                      *primary_search,
                      search_distance,
                      axisymmetric,
                      rows);
      else
        target.reinit(secondary_surface,
                      placed_tools,
                      search_distance,
                      axisymmetric,
                      rows);
      target.condense_hanging_nodes(*constraints);
    }



    // Difference quotients of the contact forces at fixed tractions (see
    // the header): one column per DoF of the nodes the loaded rows depend
    // on, from the rows that depend on it only.
    template <int dim>
    void
    CurrentMortarGeometry<dim>::contact_force_derivative(
      const std::vector<Tensor<1, dim>> &tractions,
      const ColumnSink                  &add) const
    {
      const unsigned int        n_rows = mortar.n_rows();
      std::vector<unsigned int> loaded;
      for (unsigned int j = 0; j < n_rows; ++j)
        if (tractions[j].norm() > 0. && mortar.is_integrated(j) &&
            mortar.row(j).has_partner)
          loaded.push_back(j);
      if (loaded.empty())
        return;

      // The forces of row j of coupling C: the pressure and the magnitude
      // of the tangential traction held, the directions from C's normal.
      using Forces = std::map<types::global_dof_index, double>;
      const auto row_forces =
        [&](const MortarCoupling<dim> &C, const unsigned int j, Forces &F) {
          const MortarRow<dim> &row = C.row(j);
          if (!row.has_partner)
            return;
          const Tensor<1, dim> &tau    = tractions[j];
          const Tensor<1, dim> &n0     = mortar.row(j).normal;
          const double          lambda = -(tau * n0);
          const Tensor<1, dim>  t      = tau + lambda * n0;
          Tensor<1, dim>        t_new  = t - (t * row.normal) * row.normal;
          if (t_new.norm() > 0.)
            t_new *= t.norm() / t_new.norm();
          // The nodal force D_j tau_j is held, as the condensed multiplier
          // is (the secondary node's own force, lambda_j = n_j . r_j / D_j):
          // the primary nodes take the shares M_jk / D_j of it.
          const Tensor<1, dim> force =
            mortar.row(j).weight * (-lambda * row.normal + t_new);
          const auto &dofs = C.secondary_surface().node(j).dofs;
          for (unsigned int c = 0; c < dim; ++c)
            F[dofs[c]] += force[c];
          for (const auto &[k, M] : row.primary_weights)
            for (unsigned int c = 0; c < dim; ++c)
              F[C.primary_node(k).dofs[c]] -= M / row.weight * force[c];
        };
      std::vector<Forces> base(n_rows);
      for (const unsigned int j : loaded)
        row_forces(mortar, j, base[j]);

      // One column: the change of the forces of @p rows, restricted to the
      // DoFs they couple now; the tangent is minus the derivative.
      for_each_perturbation(loaded,
                            [&](const MortarCoupling<dim>       &C,
                                const std::vector<unsigned int> &rows,
                                const Perturbation              &moved) {
                              Forces change;
                              for (const unsigned int j : rows)
                                {
                                  Forces F;
                                  row_forces(C, j, F);
                                  for (const auto &[key, value] : base[j])
                                    {
                                      const auto it = F.find(key);
                                      change[key] +=
                                        (it == F.end() ? 0. : it->second) -
                                        value;
                                    }
                                }
                              std::vector<types::global_dof_index> row_dofs;
                              std::vector<double>                  values;
                              for (const auto &[key, value] : change)
                                {
                                  row_dofs.push_back(key);
                                  values.push_back(-value / moved.eps);
                                }
                              add(row_dofs, moved.dof, values);
                            });
    }



    template <int dim>
    bool
    CurrentMortarGeometry<dim>::weighted_gap_derivative(
      const std::vector<bool> &selected,
      const VectorType        &u,
      const GapColumnSink     &add) const
    {
      std::vector<unsigned int> rows;
      for (unsigned int j = 0; j < mortar.n_rows(); ++j)
        if (selected[j] && mortar.is_integrated(j) && mortar.row(j).has_partner)
          rows.push_back(j);
      std::vector<double> base(mortar.n_rows(), 0.);
      for (const unsigned int j : rows)
        base[j] = mortar.weighted_gap(j, u);

      for_each_perturbation(
        rows,
        [&](const MortarCoupling<dim>       &C,
            const std::vector<unsigned int> &changed,
            const Perturbation              &moved) {
          for (const unsigned int j : changed)
            {
              const MortarRow<dim> &row = C.row(j);
              // A row that loses its partner by the move has no quotient.
              if (!row.has_partner)
                continue;
              // C's gap adds the displacements u, not the move: the moved
              // node's own share of the gap is added here.
              double share = 0.;
              if (moved.kind == Perturbation::Kind::secondary)
                {
                  if (moved.index == j)
                    share = -row.weight;
                }
              else
                for (const auto &[k, M] : row.primary_weights)
                  if ((moved.kind == Perturbation::Kind::primary &&
                       k == moved.index) ||
                      (moved.kind == Perturbation::Kind::tool &&
                       tool_of_primary_node(k) == moved.index))
                    share += M;
              const double gap =
                C.weighted_gap(j, u) +
                share * row.normal[moved.component] * moved.eps;
              add(j, moved.dof, (gap - base[j]) / moved.eps);
            }
        });
      return true;
    }



    template <int dim>
    void
    CurrentMortarGeometry<dim>::for_each_perturbation(
      const std::vector<unsigned int>                 &loaded,
      const std::function<void(const MortarCoupling<dim> &,
                               const std::vector<unsigned int> &,
                               const Perturbation &)> &visit) const
    {
      if (loaded.empty())
        return;
      // The nodes each row depends on.
      std::map<unsigned int, std::vector<unsigned int>> secondary_columns,
        primary_columns;
      std::vector<std::vector<unsigned int>> tool_columns(tools.size());
      for (const unsigned int j : loaded)
        {
          for (const unsigned int m : neighbourhood(j))
            secondary_columns[m].push_back(j);
          for (const auto &entry : mortar.row(j).primary_weights)
            {
              if (tools.empty())
                primary_columns[entry.first].push_back(j);
              else
                {
                  auto &rows = tool_columns[tool_of_primary_node(entry.first)];
                  if (rows.empty() || rows.back() != j)
                    rows.push_back(j);
                }
            }
        }

      ContactSurface<dim> moved_secondary(*secondary);
      MortarCoupling<dim> scratch;
      std::vector<bool>   selected(mortar.n_rows(), false);
      const auto rows_for = [&](const std::vector<unsigned int> &rows) {
        std::fill(selected.begin(), selected.end(), false);
        for (const unsigned int j : rows)
          selected[j] = true;
        return MortarCoupling<dim>::rows_to_integrate(*secondary,
                                                      *constraints,
                                                      selected);
      };

      for (const auto &[m, rows] : secondary_columns)
        {
          const double            eps = 1e-7 * mortar.row(rows[0]).mesh_size;
          const std::vector<bool> integrate_these = rows_for(rows);
          for (unsigned int c = 0; c < dim; ++c)
            {
              const Tensor<1, dim> shift =
                eps * Tensor<1, dim>(Point<dim>::unit_vector(c));
              moved_secondary.move_node(m, shift);
              integrate_rows(moved_secondary,
                             primary.get(),
                             search.get(),
                             partners,
                             integrate_these,
                             scratch);
              visit(scratch,
                    rows,
                    {Perturbation::Kind::secondary,
                     m,
                     c,
                     eps,
                     secondary->node(m).dofs[c]});
              moved_secondary.move_node(m, -shift);
            }
        }

      if (!primary_columns.empty())
        {
          ContactSurface<dim> moved_primary(*primary);
          for (const auto &[k, rows] : primary_columns)
            {
              const double eps = 1e-7 * mortar.row(rows[0]).mesh_size;
              const std::vector<bool> integrate_these = rows_for(rows);
              for (unsigned int c = 0; c < dim; ++c)
                {
                  const Tensor<1, dim> shift =
                    eps * Tensor<1, dim>(Point<dim>::unit_vector(c));
                  moved_primary.move_node(k, shift);
                  const ContactSearch<dim> moved_search(moved_primary, 0.);
                  integrate_rows(*secondary,
                                 &moved_primary,
                                 &moved_search,
                                 partners,
                                 integrate_these,
                                 scratch);
                  visit(scratch,
                        rows,
                        {Perturbation::Kind::primary,
                         k,
                         c,
                         eps,
                         primary->node(k).dofs[c]});
                  moved_primary.move_node(k, -shift);
                }
            }
        }

      for (unsigned int i = 0; i < tools.size(); ++i)
        {
          const auto &rows = tool_columns[i];
          if (rows.empty())
            continue;
          const double            eps = 1e-7 * mortar.row(rows[0]).mesh_size;
          const std::vector<bool> integrate_these = rows_for(rows);
          for (unsigned int c = 0; c < dim; ++c)
            {
              RigidSurface<dim>    moved(*placed[i]);
              const Tensor<1, dim> translation =
                partners[i].displacement +
                eps * Tensor<1, dim>(Point<dim>::unit_vector(c));
              moved.set_placement(translation, angle[i], tools[i].centre);
              std::vector<RigidPartner<dim>> moved_partners = partners;
              moved_partners[i].surface                     = &moved;
              moved_partners[i].displacement                = translation;
              integrate_rows(*secondary,
                             nullptr,
                             nullptr,
                             moved_partners,
                             integrate_these,
                             scratch);
              visit(scratch,
                    rows,
                    {Perturbation::Kind::tool,
                     i,
                     c,
                     eps,
                     tools[i].reference_node_dofs[c]});
            }
        }
    }



    // The rows depend on the nodes of their faces and, through the nodal
    // normals that the projection interpolates, on those of the faces
    // around these.
    template <int dim>
    std::vector<unsigned int>
    CurrentMortarGeometry<dim>::neighbourhood(const unsigned int j) const
    {
      std::vector<unsigned int> nodes{j};
      for (unsigned int ring = 0; ring < 2; ++ring)
        {
          std::vector<unsigned int> next = nodes;
          for (const unsigned int m : nodes)
            for (const unsigned int f : node_faces[m])
              for (const unsigned int n : secondary->face(f).nodes)
                next.push_back(n);
          std::sort(next.begin(), next.end());
          next.erase(std::unique(next.begin(), next.end()), next.end());
          nodes = std::move(next);
        }
      return nodes;
    }



    template <int dim>
    std::vector<std::vector<types::global_dof_index>>
    CurrentMortarGeometry<dim>::coupled_dof_groups() const
    {
      std::vector<std::vector<types::global_dof_index>> groups;
      for (unsigned int j = 0; j < mortar.n_rows(); ++j)
        {
          if (!mortar.is_integrated(j) || !mortar.row(j).has_partner)
            continue;
          std::vector<types::global_dof_index> dofs;
          for (const unsigned int m : neighbourhood(j))
            {
              for (const auto dof : secondary->node(m).dofs)
                dofs.push_back(dof);
              if (mortar.is_integrated(m))
                for (const auto &entry : mortar.row(m).primary_weights)
                  for (const auto dof : mortar.primary_node(entry.first).dofs)
                    dofs.push_back(dof);
            }
          std::sort(dofs.begin(), dofs.end());
          dofs.erase(std::unique(dofs.begin(), dofs.end()), dofs.end());
          groups.push_back(std::move(dofs));
        }
      return groups;
    }



    template <int dim>
    std::vector<std::vector<types::global_dof_index>>
    CurrentMortarGeometry<dim>::current_pattern() const
    {
      std::vector<std::vector<types::global_dof_index>> result(mortar.n_rows());
      for (unsigned int j = 0; j < mortar.n_rows(); ++j)
        {
          const auto &row = mortar.row(j);
          if (!row.has_partner)
            continue;
          for (const auto &entry : row.primary_weights)
            result[j].push_back(mortar.primary_node(entry.first).dofs[0]);
          std::sort(result[j].begin(), result[j].end());
          result[j].erase(std::unique(result[j].begin(), result[j].end()),
                          result[j].end());
        }
      return result;
    }



    template <int dim>
    bool
    CurrentMortarGeometry<dim>::update(const VectorType &u)
    {
      secondary->update_positions(u);
      if (primary)
        primary->update_positions(u);
      integrate(&u);

      // The pattern holds every coupling of the rows it was built for; a
      // row that now meets a primary node outside it needs a new one.
      auto now     = current_pattern();
      bool changed = false;
      for (unsigned int j = 0; j < now.size() && !changed; ++j)
        changed = !std::includes(pattern[j].begin(),
                                 pattern[j].end(),
                                 now[j].begin(),
                                 now[j].end());
      if (changed)
        {
          pattern = std::move(now);
          ++n_changes;
        }
      return changed;
    }



    template <int dim>
    const MortarCoupling<dim> &
    CurrentMortarGeometry<dim>::coupling() const
    {
      return mortar;
    }



    template <int dim>
    std::string
    CurrentMortarGeometry<dim>::primary_description() const
    {
      if (tools.empty())
        return "meshed surface, current configuration";
      std::string result = std::to_string(tools.size()) + " rigid tool" +
                           (tools.size() > 1 ? "s" : "") + " (";
      for (unsigned int i = 0; i < tools.size(); ++i)
        result += (i > 0 ? "; " : "") + tools[i].name + ": " +
                  tools[i].surface->description();
      return result + "), current configuration";
    }



    template <int dim>
    bool
    CurrentMortarGeometry<dim>::is_current_configuration() const
    {
      return true;
    }



    template <int dim>
    bool
    CurrentMortarGeometry<dim>::linearises_rows() const
    {
      return tools.empty();
    }



    template <int dim>
    void
    CurrentMortarGeometry<dim>::set_rigid_tool_gap(const RigidToolGap gap)
    {
      rigid_tool_gap = gap;
    }



    template <int dim>
    std::string
    CurrentMortarGeometry<dim>::inadmissible_state() const
    {
      if (tools.empty())
        return std::string();
      // The deepest node of the rows this rank integrates, then the
      // deepest over the ranks (the lowest rank names it on a tie).
      double       depth        = 0.;
      unsigned int deepest_tool = 0;
      Point<dim>   deepest_point;
      for (unsigned int j = 0; j < secondary->n_nodes(); ++j)
        if (mortar.is_integrated(j))
          for (unsigned int i = 0; i < tools.size(); ++i)
            {
              const Point<dim> &x = secondary->node(j).position;
              const double      d = -placed[i]->closest_point(x).distance;
              if (d > depth)
                {
                  depth         = d;
                  deepest_tool  = i;
                  deepest_point = x;
                }
            }
      const MPI_Comm comm = dof_handler.get_triangulation().get_communicator();
      const double   largest = Utilities::MPI::max(depth, comm);
      if (!(largest > search_distance))
        return std::string();
      const unsigned int rank = Utilities::MPI::this_mpi_process(comm);
      const unsigned int namer =
        Utilities::MPI::min(depth == largest ? rank : ~0u, comm);
      std::vector<double> named(dim + 1, 0.);
      if (rank == namer)
        {
          for (unsigned int c = 0; c < dim; ++c)
            named[c] = deepest_point[c];
          named[dim] = deepest_tool;
        }
      Utilities::MPI::sum(named, comm, named);
      std::ostringstream message;
      message << "the secondary node at (";
      for (unsigned int c = 0; c < dim; ++c)
        message << (c > 0 ? ", " : "") << named[c];
      message << ") lies " << largest << " mm inside the tool '"
              << tools[static_cast<unsigned int>(named[dim])].name
              << "', beyond the search distance (" << search_distance
              << " mm): the iterate has passed through the tool";
      return message.str();
    }



    template <int dim>
    void
    CurrentMortarGeometry<dim>::set_load_state(const Solvers::LoadState &state)
    {
      for (unsigned int i = 0; i < tools.size(); ++i)
        angle[i] = tools[i].rotation ? tools[i].rotation(state) : 0.;
    }



    template <int dim>
    void
    CurrentMortarGeometry<dim>::commit()
    {
      accepted_angle = angle;
      for (unsigned int j = 0; j < mortar.n_rows(); ++j)
        accepted_normals[j] = mortar.row(j).normal;
    }



    template <int dim>
    std::vector<Tensor<1, dim>>
    CurrentMortarGeometry<dim>::accepted_relative_displacements(
      const VectorType &u_accepted) const
    {
      std::vector<Tensor<1, dim>> result =
        ContactGeometry<dim>::accepted_relative_displacements(u_accepted);
      if (tools.empty())
        {
          // The accepted relative position of the pair,
          // (sum_k M_jk x_k - D_j x_j)/D_j at the accepted positions, turns
          // with the surface: it is compared with the current one after
          // the rotation Q_j that takes the accepted normal to the current
          // one, so that a rigid motion of both bodies is no slip also
          // where the mortar partner point lies off the node (by the
          // pointwise gap times the turn of the normal field).
          for (unsigned int j = 0; j < mortar.n_rows(); ++j)
            {
              const auto &row = mortar.row(j);
              if (!mortar.is_integrated(j) || row.weight == 0. ||
                  !row.has_partner)
                continue;
              // sum_k M_jk = D_j: differences of nearby points.
              const Point<dim> &X_j = secondary->node(j).reference_position;
              Tensor<1, dim>    reference;
              for (const auto &[k, M] : row.primary_weights)
                reference += M / row.weight *
                             (mortar.primary_node(k).reference_position - X_j);
              const Tensor<2, dim> Q =
                rotation_between(accepted_normals[j], row.normal);
              result[j] = Q * (result[j] + reference) - reference;
            }
          return result;
        }
      // A partner point x of tool i, now at c + s + R(theta) (Y - c), was at
      // c + s_old + R(theta_old) (Y - c): besides the translation (read from
      // the reference node's DoFs) it moved by (I - R_old R^T)(x - s - c),
      // where x - s is the stored position of the partner node.
      std::vector<Tensor<2, dim>> turn(tools.size());
      bool                        turned = false;
      for (unsigned int i = 0; i < tools.size(); ++i)
        {
          RigidSurface<dim> old(*tools[i].surface);
          old.set_placement(Tensor<1, dim>(),
                            accepted_angle[i],
                            tools[i].centre);
          turn[i] = Tensor<2, dim>(unit_symmetric_tensor<dim>()) -
                    old.rotation() * transpose(placed[i]->rotation());
          turned = turned || angle[i] != accepted_angle[i];
        }
      if (!turned)
        return result;
      for (unsigned int j = 0; j < mortar.n_rows(); ++j)
        {
          const auto &row = mortar.row(j);
          if (!mortar.is_integrated(j) || row.weight == 0.)
            continue;
          for (const auto &[k, M] : row.primary_weights)
            {
              const unsigned int i = tool_of_primary_node(k);
              result[j] -=
                M / row.weight *
                (turn[i] *
                 (mortar.primary_node(k).reference_position - tools[i].centre));
            }
        }
      return result;
    }



    template <int dim>
    std::vector<types::global_dof_index>
    CurrentMortarGeometry<dim>::dofs_read_by_update() const
    {
      std::vector<types::global_dof_index> dofs;
      for (const auto *surface : {secondary.get(), primary.get()})
        if (surface != nullptr)
          for (unsigned int n = 0; n < surface->n_nodes(); ++n)
            for (const auto dof : surface->node(n).dofs)
              dofs.push_back(dof);
      for (const auto &tool : tools)
        for (const auto dof : tool.reference_node_dofs)
          dofs.push_back(dof);
      std::sort(dofs.begin(), dofs.end());
      dofs.erase(std::unique(dofs.begin(), dofs.end()), dofs.end());
      return dofs;
    }



    template <int dim>
    unsigned int
    CurrentMortarGeometry<dim>::n_tools() const
    {
      return tools.size();
    }



    template <int dim>
    const RigidTool<dim> &
    CurrentMortarGeometry<dim>::tool(const unsigned int i) const
    {
      AssertIndexRange(i, tools.size());
      return tools[i];
    }



    template <int dim>
    unsigned int
    CurrentMortarGeometry<dim>::tool_of_primary_node(const unsigned int k) const
    {
      AssertThrow(!tools.empty(),
                  ExcMessage("The primary side is a meshed surface."));
      return k % tools.size();
    }



    template <int dim>
    const RigidSurface<dim> &
    CurrentMortarGeometry<dim>::placed_surface(const unsigned int i) const
    {
      AssertIndexRange(i, placed.size());
      return *placed[i];
    }



    template <int dim>
    double
    CurrentMortarGeometry<dim>::tool_angle(const unsigned int i) const
    {
      AssertIndexRange(i, angle.size());
      return angle[i];
    }



    template <int dim>
    std::vector<ToolLoad<dim>>
    CurrentMortarGeometry<dim>::tool_loads(
      const ContactState<dim> &state,
      const IndexSet          &locally_owned,
      const MPI_Comm           mpi_communicator) const
    {
      std::vector<ToolLoad<dim>> loads(tools.size());
      for (unsigned int j = 0; j < mortar.n_rows(); ++j)
        {
          const MortarRow<dim> &row = mortar.row(j);
          if (!row.has_partner ||
              !locally_owned.is_element(secondary->node(j).dofs[0]))
            continue;
          const NodeState<dim> &node = state.node(j);
          const Tensor<1, dim>  traction =
            -node.pressure * row.normal + node.tangential_traction;
          for (const auto &[k, M] : row.primary_weights)
            {
              const unsigned int   i     = tool_of_primary_node(k);
              const Tensor<1, dim> force = -M * traction;
              // The stored point is the partner point less the tool's
              // translation, and so is the stored centre: their difference
              // is the lever arm where the tool is now.
              const Tensor<1, dim> arm =
                mortar.primary_node(k).reference_position - tools[i].centre;
              loads[i].force += force;
              if constexpr (dim == 2)
                loads[i].moment[2] += arm[0] * force[1] - arm[1] * force[0];
              else
                loads[i].moment += cross_product_3d(arm, force);
            }
        }
      for (auto &load : loads)
        {
          load.force  = Utilities::MPI::sum(load.force, mpi_communicator);
          load.moment = Utilities::MPI::sum(load.moment, mpi_communicator);
        }
      return loads;
    }



    template <int dim>
    unsigned int
    CurrentMortarGeometry<dim>::n_pattern_changes() const
    {
      return n_changes;
    }



    template <int dim>
    std::unique_ptr<ContactGeometry<dim>>
    create_mortar_geometry(const DoFHandler<dim>   &dof_handler,
                           const Mapping<dim>      &mapping,
                           const ContactParameters &contact,
                           const bool               finite_strain,
                           const bool               axisymmetric)
    {
      if (contact.in_current_configuration(finite_strain))
        return std::make_unique<CurrentMortarGeometry<dim>>(
          dof_handler,
          mapping,
          contact.secondary_boundary_id,
          contact.primary_boundary_id,
          contact.search_distance,
          axisymmetric);
      return std::make_unique<ReferenceMortarGeometry<dim>>(
        dof_handler,
        mapping,
        contact.secondary_boundary_id,
        contact.primary_boundary_id,
        contact.search_distance,
        axisymmetric);
    }



    template <int dim>
    std::unique_ptr<ContactGeometry<dim>>
    create_mortar_geometry(
      const DoFHandler<dim>                          &dof_handler,
      const Mapping<dim>                             &mapping,
      const ContactParameters                        &contact,
      const bool                                      finite_strain,
      const std::string                              &name,
      const std::shared_ptr<const RigidSurface<dim>> &rigid,
      const std::array<types::global_dof_index, dim> &reference_node_dofs,
      const bool                                      axisymmetric)
    {
      if (contact.in_current_configuration(finite_strain))
        {
          RigidTool<dim> tool;
          tool.name                = name;
          tool.surface             = rigid;
          tool.reference_node_dofs = reference_node_dofs;
          auto geometry = std::make_unique<CurrentMortarGeometry<dim>>(
            dof_handler,
            mapping,
            contact.secondary_boundary_id,
            std::vector<RigidTool<dim>>{tool},
            contact.search_distance,
            axisymmetric);
          geometry->set_rigid_tool_gap(contact.rigid_tool_gap);
          return geometry;
        }
      return std::make_unique<ReferenceMortarGeometry<dim>>(
        dof_handler,
        mapping,
        contact.secondary_boundary_id,
        rigid,
        reference_node_dofs,
        contact.search_distance,
        axisymmetric);
    }

    template class CurrentMortarGeometry<2>;
    template class CurrentMortarGeometry<3>;
#define INSTANTIATE(dim)                                                      \
  template std::unique_ptr<ContactGeometry<dim>> create_mortar_geometry<dim>( \
    const DoFHandler<dim> &,                                                  \
    const Mapping<dim> &,                                                     \
    const ContactParameters &,                                                \
    const bool,                                                               \
    const bool);                                                              \
  template std::unique_ptr<ContactGeometry<dim>> create_mortar_geometry<dim>( \
    const DoFHandler<dim> &,                                                  \
    const Mapping<dim> &,                                                     \
    const ContactParameters &,                                                \
    const bool,                                                               \
    const std::string &,                                                      \
    const std::shared_ptr<const RigidSurface<dim>> &,                         \
    const std::array<types::global_dof_index, dim> &,                         \
    const bool);
    INSTANTIATE(2)
    INSTANTIATE(3)
#undef INSTANTIATE
  } // namespace Contact
} // namespace Common
