#include <common/contact/active_set_policy.h>
#include <common/contact/contact_search.h>

#include <deal.II/base/numbers.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace Common
{
  namespace Contact
  {
    using namespace dealii;

    template <int dim>
    ActiveSetPolicy<dim>::ActiveSetPolicy(const ContactParameters &parameters,
                                          const double reference_modulus)
      : ncp_factor(parameters.ncp_factor)
      , tangential_ncp_factor(parameters.tangential_ncp_factor)
      , reference_modulus(reference_modulus)
      , accelerate_release(parameters.accelerate_release)
      , cycling(false)
      , last_update_extrapolated(false)
      , extrapolation_enabled(parameters.accelerate_release)
    {}



    template <int dim>
    double
    ActiveSetPolicy<dim>::ncp_constant(const double mesh_size) const
    {
      return ncp_factor * reference_modulus / mesh_size;
    }



    template <int dim>
    double
    ActiveSetPolicy<dim>::tangential_ncp_constant(const double mesh_size) const
    {
      return tangential_ncp_factor * reference_modulus / mesh_size;
    }



    template <int dim>
    void
    ActiveSetPolicy<dim>::initialize(
      const std::vector<NodeKinematics<dim>> &nodes,
      const FrictionModel<dim>               &friction,
      ContactState<dim>                      &state) const
    {
      const unsigned int       n = nodes.size();
      std::vector<PointStatus> status(n, PointStatus::open);
      for (unsigned int j = 0; j < n; ++j)
        {
          // The weighted gap averages over the node's support and is not
          // zero at a touching node; the pointwise gap is, up to round-off.
          const bool touching =
            nodes[j].paired && nodes[j].nodal_gap <= 1e-8 * nodes[j].mesh_size;
          status[j] =
            touching ? friction.status_on_contact() : PointStatus::open;
        }
      // Close the nearest node that carries a multiplier if no touching
      // one does (every rank holds every row, so all decide alike).
      unsigned int nearest = numbers::invalid_unsigned_int;
      bool         held    = false;
      for (unsigned int j = 0; j < n; ++j)
        {
          if (!nodes[j].paired || nodes[j].weight <= 0.)
            continue;
          held = held || status[j] != PointStatus::open;
          if (nearest == numbers::invalid_unsigned_int ||
              nodes[j].nodal_gap < nodes[nearest].nodal_gap)
            nearest = j;
        }
      if (!held && nearest != numbers::invalid_unsigned_int)
        status[nearest] = friction.status_on_contact();
      state.reset(status);
    }



    template <int dim>
    void
    ActiveSetPolicy<dim>::begin_step(const ContactState<dim> &state)
    {
      std::vector<NodeState<dim>> nodes(state.n_nodes());
      for (unsigned int j = 0; j < state.n_nodes(); ++j)
        nodes[j] = state.node(j);
      history.clear();
      history.push_back(codes(state, nodes));
      cycling                  = false;
      last_update_extrapolated = false;
      extrapolation_enabled    = accelerate_release;
    }



    template <int dim>
    std::vector<int>
    ActiveSetPolicy<dim>::codes(const ContactState<dim>           &state,
                                const std::vector<NodeState<dim>> &nodes) const
    {
      std::vector<int> result(nodes.size());
      for (unsigned int j = 0; j < nodes.size(); ++j)
        {
          const NodeState<dim> &s   = nodes[j];
          const auto &free_tangents = state.directions().free_tangents(j);
          result[j]                 = static_cast<int>(s.status);
          // Along a single free tangent (2D, or a symmetry plane in 3D)
          // the slip direction is one of its two senses.
          if (free_tangents.size() == 1 && s.status == PointStatus::slip &&
              s.slip_direction.norm() > 0.)
            result[j] += (s.slip_direction * free_tangents[0] < 0. ? 10 : 0);
        }
      return result;
    }



    template <int dim>
    std::pair<double, Tensor<1, dim>>
    ActiveSetPolicy<dim>::complementarity(
      const unsigned int                      j,
      const std::vector<NodeKinematics<dim>> &nodes,
      const NormalEnforcement<dim>           &normal,
      const FrictionModel<dim>               &friction,
      const ContactState<dim>                &state) const
    {
      const NodeKinematics<dim> &kinematics = nodes[j];
      const NodeState<dim>      &node       = state.node(j);
      const double       gap = kinematics.weighted_gap / kinematics.weight;
      const double       c   = ncp_constant(kinematics.mesh_size);
      const double       C_n = state.directions().normally_free(j) ?
                                 normal.complementarity(node.pressure, gap, c) :
                                 0.;
      FrictionPoint<dim> point;
      point.traction = node.tangential_traction;
      point.slip_increment =
        state.slip_increment(j, kinematics.relative_displacement);
      point.normal_pressure = std::max(0., node.pressure - c * gap);
      point.c               = tangential_ncp_constant(kinematics.mesh_size);
      point.n_free_tangents = state.directions().free_tangents(j).size();
      return {C_n, friction.complementarity(point)};
    }



    template <int dim>
    unsigned int
    ActiveSetPolicy<dim>::update(const std::vector<NodeKinematics<dim>> &nodes,
                                 const NormalEnforcement<dim>           &normal,
                                 const FrictionModel<dim> &friction,
                                 ContactState<dim>        &state)
    {
      const unsigned int n = nodes.size();
      std::vector<bool>  closed(n, false), next(n, false);
      unsigned int       n_closed = 0, n_opened = 0;
      for (unsigned int j = 0; j < n; ++j)
        {
          closed[j] = state.is_closed(j);
          if (!nodes[j].paired)
            continue;
          const double gap = nodes[j].weighted_gap / nodes[j].weight;
          next[j]          = normal.is_closed(state.node(j).pressure,
                                     gap,
                                     ncp_constant(nodes[j].mesh_size));
          n_closed += (next[j] && !closed[j]);
          n_opened += (!next[j] && closed[j]);
        }

      if (n_closed > 0 && last_update_extrapolated)
        extrapolation_enabled = false;
      last_update_extrapolated = false;

      if (extrapolation_enabled && n_closed == 0 && n_opened > 0)
        {
          std::vector<unsigned int> opened, kept;
          for (unsigned int j = 0; j < n; ++j)
            if (closed[j] && !next[j])
              opened.push_back(j);
            else if (next[j])
              kept.push_back(j);
          std::vector<unsigned int> also_opened;
          if (!kept.empty())
            {
              // Nearest-point queries on an R-tree of the closed set
              // (NearestPoints): O(n log n), not a loop over all pairs.
              std::vector<Point<dim>> positions(n);
              for (unsigned int j = 0; j < n; ++j)
                positions[j] = nodes[j].position;
              NearestPoints<dim> closed_set(positions, kept);
              // Distance of each opened node to the closed set.
              std::vector<double> band(opened.size());
              for (unsigned int r = 0; r < opened.size(); ++r)
                band[r] = positions[opened[r]].distance(
                  positions[closed_set.nearest(positions[opened[r]])]);
              // The closed nodes within twice an opened node's band: the
              // nearest remaining one while it lies inside, each taken out
              // of the tree once found.
              for (unsigned int r = 0; r < opened.size(); ++r)
                {
                  const Point<dim> &x = positions[opened[r]];
                  for (unsigned int j = closed_set.nearest(x);
                       j != numbers::invalid_unsigned_int &&
                       positions[j].distance(x) < 2. * band[r] * (1. - 1e-10);
                       j = closed_set.nearest(x))
                    {
                      also_opened.push_back(j);
                      closed_set.remove(j);
                    }
                }
            }
          // Never open the whole zone: keep the plain step then.
          if (!kept.empty() && also_opened.size() < kept.size())
            {
              for (const unsigned int j : also_opened)
                next[j] = false;
              last_update_extrapolated = !also_opened.empty();
            }
        }

      // Stick or slip for the closed nodes.
      std::vector<NodeState<dim>> current(n);
      for (unsigned int j = 0; j < n; ++j)
        current[j] = state.node(j);
      std::vector<NodeState<dim>> proposed = current;
      for (unsigned int j = 0; j < n; ++j)
        {
          proposed[j].slip_direction    = Tensor<1, dim>();
          proposed[j].turning_stiffness = 0.;
          if (!next[j])
            {
              proposed[j].status = PointStatus::open;
              continue;
            }
          const double       c = ncp_constant(nodes[j].mesh_size);
          FrictionPoint<dim> point;
          point.traction = current[j].tangential_traction;
          point.slip_increment =
            state.slip_increment(j, nodes[j].relative_displacement);
          point.normal_pressure =
            std::max(0.,
                     current[j].pressure -
                       c * nodes[j].weighted_gap / nodes[j].weight);
          point.c               = tangential_ncp_constant(nodes[j].mesh_size);
          point.n_free_tangents = state.directions().free_tangents(j).size();
          const FrictionStatus<dim> tangential = friction.closed_status(point);
          proposed[j].status                   = tangential.status;
          proposed[j].slip_direction           = tangential.slip_direction;
          proposed[j].turning_stiffness        = tangential.turning_stiffness;
        }

      // A set seen before in this step means ping-pong (typically a corner
      // and a mid-side node of a Q2 face trading places at the contact
      // edge, or a node at the stick-slip boundary). Then change only the
      // point with the largest complementarity violation whose change
      // leads to a set not seen yet.
      const std::vector<int> current_codes = codes(state, current);
      std::vector<int>       next_codes    = codes(state, proposed);
      const auto             seen = [this](const std::vector<int> &set) {
        return std::find(history.begin(), history.end(), set) != history.end();
      };
      cycling = false;
      if (next_codes != current_codes && seen(next_codes))
        {
          extrapolation_enabled = false;
          std::vector<std::pair<double, unsigned int>> violations;
          for (unsigned int j = 0; j < n; ++j)
            if (next_codes[j] != current_codes[j])
              {
                const auto [C_n, C_t] =
                  complementarity(j, nodes, normal, friction, state);
                violations.emplace_back((std::abs(C_n) + C_t.norm()) *
                                          nodes[j].weight,
                                        j);
              }
          std::sort(violations.rbegin(), violations.rend());
          cycling = true;
          for (const auto &[size, j] : violations)
            {
              std::vector<int> single = current_codes;
              single[j]               = next_codes[j];
              if (!seen(single))
                {
                  std::vector<NodeState<dim>> one = current;
                  one[j].status                   = proposed[j].status;
                  one[j].slip_direction           = proposed[j].slip_direction;
                  one[j].turning_stiffness = proposed[j].turning_stiffness;
                  proposed                 = one;
                  next_codes               = single;
                  cycling                  = false;
                  break;
                }
            }
        }

      unsigned int n_changed = 0;
      for (unsigned int j = 0; j < n; ++j)
        n_changed += (next_codes[j] != current_codes[j]);
      // In 3D a slip direction may turn without changing the code.
      for (unsigned int j = 0; j < n; ++j)
        {
          NodeState<dim> &node   = state.node(j);
          node.status            = proposed[j].status;
          node.slip_direction    = proposed[j].slip_direction;
          node.turning_stiffness = proposed[j].turning_stiffness;
        }
      history.push_back(next_codes);
      return n_changed;
    }



    template <int dim>
    bool
    ActiveSetPolicy<dim>::is_cycling() const
    {
      return cycling;
    }



    template <int dim>
    double
    ActiveSetPolicy<dim>::complementarity_norm(
      const std::vector<NodeKinematics<dim>> &nodes,
      const NormalEnforcement<dim>           &normal,
      const FrictionModel<dim>               &friction,
      const ContactState<dim>                &state) const
    {
      if (!normal.has_multipliers())
        return 0.;
      double sum = 0.;
      for (unsigned int j = 0; j < nodes.size(); ++j)
        {
          if (!nodes[j].paired)
            continue;
          const auto [C_n, C_t] =
            complementarity(j, nodes, normal, friction, state);
          sum +=
            (C_n * C_n + C_t.norm_square()) * nodes[j].weight * nodes[j].weight;
        }
      return std::sqrt(sum);
    }



    template <int dim>
    bool
    ActiveSetPolicy<dim>::touches_search_edge(
      const MortarCoupling<dim> &coupling,
      const ContactState<dim>   &state)
    {
      const auto &surface = coupling.secondary_surface();
      for (unsigned int f = 0; f < surface.n_faces(); ++f)
        {
          bool any_active = false, any_unpaired = false;
          for (const unsigned int j : surface.face(f).nodes)
            {
              any_active = any_active || state.is_closed(j);
              // A node without measure (on the axis) bounds no search.
              any_unpaired = any_unpaired || (!coupling.row(j).has_partner &&
                                              coupling.row(j).weight > 0.);
            }
          if (any_active && any_unpaired)
            return true;
        }
      return false;
    }

    template class ActiveSetPolicy<2>;
    template class ActiveSetPolicy<3>;
  } // namespace Contact
} // namespace Common
