#include <common/contact/active_set_policy.h>
#include <common/contact/contact_search.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/numbers.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

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
      , initial_active_set(parameters.initial_active_set)
      , cycling(false)
      , revisited_held_set(false)
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
      const RowPartition      &rows = state.rows();
      const unsigned int       n    = nodes.size();
      std::vector<PointStatus> status(n, PointStatus::open);
      for (unsigned int j = 0; j < n; ++j)
        {
          if (!rows.is_held(j))
            continue;
          // The weighted gap averages over the node's support and is not
          // zero at a touching node; the pointwise gap is, up to round-off.
          const bool touching =
            nodes[j].paired && nodes[j].nodal_gap <= 1e-8 * nodes[j].mesh_size;
          status[j] =
            touching ? friction.status_on_contact() : PointStatus::open;
        }
      // Close the nearest node that carries a multiplier if no touching
      // one does: each rank's nearest owned node, then the smallest gap
      // over the ranks (the first node on ties, as in serial).
      unsigned int nearest = numbers::invalid_unsigned_int;
      bool         held    = false;
      for (unsigned int j = 0; j < n; ++j)
        {
          if (!rows.is_owned(j) || !nodes[j].paired || nodes[j].weight <= 0.)
            continue;
          held = held || status[j] != PointStatus::open;
          if (nearest == numbers::invalid_unsigned_int ||
              nodes[j].nodal_gap < nodes[nearest].nodal_gap)
            nearest = j;
        }
      if (rows.is_distributed())
        {
          const MPI_Comm comm = rows.communicator();
          held = Utilities::MPI::max(static_cast<unsigned int>(held), comm) > 0;
          struct
          {
            double gap;
            int    j;
          } local{std::numeric_limits<double>::infinity(),
                  std::numeric_limits<int>::max()},
            global;
          if (nearest != numbers::invalid_unsigned_int)
            local = {nodes[nearest].nodal_gap, static_cast<int>(nearest)};
          const int ierr =
            MPI_Allreduce(&local, &global, 1, MPI_DOUBLE_INT, MPI_MINLOC, comm);
          AssertThrowMPI(ierr);
          nearest = global.j == std::numeric_limits<int>::max() ?
                      numbers::invalid_unsigned_int :
                      static_cast<unsigned int>(global.j);
        }
      if (!held && nearest != numbers::invalid_unsigned_int &&
          rows.is_held(nearest))
        status[nearest] = friction.status_on_contact();

      if (initial_active_set == InitialActiveSet::nearest_per_body)
        {
          // Each rank's nearest owned node per body (its gap, index and
          // position), then the nearest over the ranks (the first node on
          // ties, as in serial).
          using Candidate =
            std::pair<std::pair<double, unsigned int>, Point<dim>>;
          std::map<types::global_dof_index, Candidate> best;
          for (unsigned int j = 0; j < n; ++j)
            {
              if (!rows.is_owned(j) || !nodes[j].paired ||
                  nodes[j].weight <= 0.)
                continue;
              const auto it = best.find(nodes[j].partner);
              if (it == best.end() ||
                  nodes[j].nodal_gap < it->second.first.first)
                best[nodes[j].partner] = {{nodes[j].nodal_gap, j},
                                          nodes[j].position};
            }
          if (rows.is_distributed())
            {
              std::map<types::global_dof_index, Candidate> merged;
              for (const auto &part :
                   Utilities::MPI::all_gather(rows.communicator(), best))
                for (const auto &[body, candidate] : part)
                  {
                    const auto it = merged.find(body);
                    if (it == merged.end() ||
                        candidate.first < it->second.first)
                      merged[body] = candidate;
                  }
              best = merged;
            }
          // In 3D also the nodes of that node's line along z: the line of
          // first contact of a body extruded along z.
          std::fill(status.begin(), status.end(), PointStatus::open);
          for (unsigned int j = 0; j < n; ++j)
            {
              if (!rows.is_held(j) || !nodes[j].paired || nodes[j].weight <= 0.)
                continue;
              const auto it = best.find(nodes[j].partner);
              if (it == best.end())
                continue;
              const Point<dim> &x       = it->second.second;
              const bool        on_line = dim == 3 &&
                                   std::abs(nodes[j].position[0] - x[0]) <=
                                     1e-8 * nodes[j].mesh_size &&
                                   std::abs(nodes[j].position[1] - x[1]) <=
                                     1e-8 * nodes[j].mesh_size;
              if (j == it->second.first.second || on_line)
                status[j] = friction.status_on_contact();
            }
        }
      state.reset(status);
    }



    template <int dim>
    void
    ActiveSetPolicy<dim>::restart_history(const ContactState<dim> &state)
    {
      const std::vector<int> current = codes(state);
      // The sets of the earlier equilibria stay seen: each had a node on
      // the wrong side, so none is the solution, and returning to one
      // would repeat the cycle (A, B, A ...) that a penalty, whose
      // complementarity residual vanishes, cannot otherwise detect.
      history.clear();
      for (const auto &set : equilibrium_sets)
        if (set != current)
          history.push_back(set);
      history_residual.assign(history.size(), 0.);
      history.push_back(current);
      history_residual.push_back(std::numeric_limits<double>::infinity());
      if (std::find(equilibrium_sets.begin(),
                    equilibrium_sets.end(),
                    current) == equilibrium_sets.end())
        equilibrium_sets.push_back(current);
      cycling = false;
    }



    template <int dim>
    void
    ActiveSetPolicy<dim>::begin_linearisation(const ContactState<dim> &state)
    {
      saved_history          = history;
      saved_history_residual = history_residual;
      saved_equilibrium_sets = equilibrium_sets;
      history.assign(1, codes(state));
      history_residual.assign(1, std::numeric_limits<double>::infinity());
      equilibrium_sets.clear();
      cycling = false;
    }



    template <int dim>
    void
    ActiveSetPolicy<dim>::end_linearisation(const ContactState<dim> &state)
    {
      history          = saved_history;
      history_residual = saved_history_residual;
      equilibrium_sets = saved_equilibrium_sets;
      if (history.empty())
        {
          history.emplace_back();
          history_residual.push_back(std::numeric_limits<double>::infinity());
        }
      history.back() = codes(state);
      cycling        = false;
    }



    template <int dim>
    void
    ActiveSetPolicy<dim>::begin_step(const ContactState<dim> &state)
    {
      equilibrium_sets.clear();
      history.assign(1, codes(state));
      history_residual.assign(1, std::numeric_limits<double>::infinity());
      cycling                  = false;
      last_update_extrapolated = false;
      extrapolation_enabled    = accelerate_release;
    }



    template <int dim>
    std::vector<int>
    ActiveSetPolicy<dim>::codes(const ContactState<dim> &state) const
    {
      std::vector<NodeState<dim>> nodes(state.n_nodes());
      for (unsigned int j = 0; j < state.n_nodes(); ++j)
        nodes[j] = state.node(j);
      return codes(state, nodes);
    }



    template <int dim>
    std::vector<int>
    ActiveSetPolicy<dim>::codes(const ContactState<dim>           &state,
                                const std::vector<NodeState<dim>> &nodes) const
    {
      const RowPartition &rows = state.rows();
      std::vector<int>    result;
      result.reserve(rows.n_owned(nodes.size()));
      for (unsigned int j = 0; j < nodes.size(); ++j)
        {
          if (!rows.is_owned(j))
            continue;
          const NodeState<dim> &s   = nodes[j];
          const auto &free_tangents = state.directions().free_tangents(j);
          int         code          = static_cast<int>(s.status);
          // Along a single free tangent (2D, or a symmetry plane in 3D)
          // the slip direction is one of its two senses.
          if (free_tangents.size() == 1 && s.status == PointStatus::slip &&
              s.slip_direction.norm() > 0.)
            code += (s.slip_direction * free_tangents[0] < 0. ? 10 : 0);
          result.push_back(code);
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
                                 ContactState<dim>        &state,
                                 const double              residual,
                                 const bool                one_point)
    {
      // The current set (the last entry) produced the current iterate.
      // An entry counts as seen unless the iteration has progressed by a
      // decade since that use (a set used again has one entry per use).
      if (residual >= 0.)
        history_residual.back() = residual;
      history_counts.assign(history.size(), true);
      if (residual >= 0.)
        for (unsigned int i = 0; i < history.size(); ++i)
          history_counts[i] = !(residual < 0.1 * history_residual[i]);
      // Each rank decides the nodes it owns; counts and the safeguards
      // that look at every node are collectives, so that every rank takes
      // the same branch.
      const RowPartition       &rows        = state.rows();
      const MPI_Comm            comm        = rows.communicator();
      const bool                distributed = rows.is_distributed();
      const unsigned int        n           = nodes.size();
      std::vector<bool>         closed(n, false), next(n, false);
      std::vector<unsigned int> n_closed_opened(2, 0);
      for (unsigned int j = 0; j < n; ++j)
        {
          if (!rows.is_owned(j))
            continue;
          closed[j] = state.is_closed(j);
          if (!nodes[j].paired)
            continue;
          const double gap = nodes[j].weighted_gap / nodes[j].weight;
          next[j]          = normal.is_closed(state.node(j).pressure,
                                     gap,
                                     ncp_constant(nodes[j].mesh_size));
          n_closed_opened[0] += (next[j] && !closed[j]);
          n_closed_opened[1] += (!next[j] && closed[j]);
        }
      if (distributed)
        Utilities::MPI::sum(n_closed_opened, comm, n_closed_opened);
      const unsigned int n_closed = n_closed_opened[0];
      const unsigned int n_opened = n_closed_opened[1];

      if (n_closed > 0 && last_update_extrapolated)
        extrapolation_enabled = false;
      last_update_extrapolated = false;

      if (extrapolation_enabled && n_closed == 0 && n_opened > 0)
        extrapolate_release(nodes, rows, closed, next);

      // Stick or slip for the closed nodes.
      std::vector<NodeState<dim>> current(n);
      for (unsigned int j = 0; j < n; ++j)
        current[j] = state.node(j);
      std::vector<NodeState<dim>> proposed = current;
      for (unsigned int j = 0; j < n; ++j)
        {
          if (!rows.is_owned(j))
            continue;
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

      // On equilibria (one point at a time), a slipping node whose slip
      // would reverse sticks first: near zero pressure the two senses
      // trade places at every equilibrium, and the state between them is
      // stick.
      if (one_point)
        for (unsigned int j = 0; j < n; ++j)
          if (rows.is_owned(j) && current[j].status == PointStatus::slip &&
              proposed[j].status == PointStatus::slip &&
              current[j].slip_direction * proposed[j].slip_direction < 0.)
            {
              proposed[j].status            = PointStatus::stick;
              proposed[j].slip_direction    = Tensor<1, dim>();
              proposed[j].turning_stiffness = 0.;
            }

      // A set seen before in this step means ping-pong (typically a corner
      // and a mid-side node of a Q2 face trading places at the contact
      // edge, or a node at the stick-slip boundary). Then change only the
      // point with the largest complementarity violation whose change
      // leads to a set not seen yet. The codes and the history hold the
      // owned nodes; a set is seen if it matches an entry on every rank.
      const std::vector<int> current_codes = codes(state, current);
      std::vector<int>       next_codes    = codes(state, proposed);
      const auto             seen          = [&](const std::vector<int> &set) {
        std::vector<unsigned int> mismatch(history.size());
        for (unsigned int i = 0; i < history.size(); ++i)
          mismatch[i] = (!history_counts[i] || history[i] != set);
        if (distributed)
          Utilities::MPI::sum(mismatch, comm, mismatch);
        return std::find(mismatch.begin(), mismatch.end(), 0u) !=
               mismatch.end();
      };
      bool changed = next_codes != current_codes;
      if (distributed)
        changed =
          Utilities::MPI::max(static_cast<unsigned int>(changed), comm) > 0;
      cycling            = false;
      revisited_held_set = false;
      if (changed && (one_point || seen(next_codes)))
        {
          extrapolation_enabled         = false;
          auto [j_single, back_to_held] = single_change(nodes,
                                                        normal,
                                                        friction,
                                                        state,
                                                        current_codes,
                                                        next_codes);
          // Every single change leads to a set seen before: a node that
          // trades a slip for another state (opening, or the slip of the
          // other sense) and back may have its solution in the state
          // between, stick. Try the changes with stick in place of the
          // state a slipping node would take, or of the slip it would
          // take.
          if (j_single == numbers::invalid_unsigned_int &&
              friction.has_friction())
            {
              std::vector<NodeState<dim>> sticking = proposed;
              unsigned int                n_stick  = 0;
              for (unsigned int j = 0, l = 0; j < n; ++j)
                if (rows.is_owned(j))
                  {
                    if (next_codes[l] != current_codes[l] &&
                        current[j].status != PointStatus::stick &&
                        (proposed[j].status == PointStatus::slip ||
                         current[j].status == PointStatus::slip))
                      {
                        sticking[j].status            = PointStatus::stick;
                        sticking[j].slip_direction    = Tensor<1, dim>();
                        sticking[j].turning_stiffness = 0.;
                        ++n_stick;
                      }
                    ++l;
                  }
              if (distributed)
                n_stick = Utilities::MPI::sum(n_stick, comm);
              if (n_stick > 0)
                {
                  const std::vector<int> stick_codes = codes(state, sticking);
                  const auto [j_stick, back]         = single_change(nodes,
                                                             normal,
                                                             friction,
                                                             state,
                                                             current_codes,
                                                             stick_codes);
                  if (j_stick != numbers::invalid_unsigned_int)
                    {
                      proposed     = sticking;
                      next_codes   = stick_codes;
                      j_single     = j_stick;
                      back_to_held = back;
                    }
                }
            }
          revisited_held_set = back_to_held;
          cycling            = j_single == numbers::invalid_unsigned_int;
          // A cycle changes nothing: the caller decides what follows.
          if (cycling)
            {
              proposed   = current;
              next_codes = current_codes;
            }
          else
            for (unsigned int j = 0, l = 0; j < n; ++j)
              if (rows.is_owned(j))
                {
                  if (j == j_single)
                    {
                      NodeState<dim> one    = current[j];
                      one.status            = proposed[j].status;
                      one.slip_direction    = proposed[j].slip_direction;
                      one.turning_stiffness = proposed[j].turning_stiffness;
                      proposed[j]           = one;
                    }
                  else
                    {
                      proposed[j]   = current[j];
                      next_codes[l] = current_codes[l];
                    }
                  ++l;
                }
        }

      unsigned int n_changed = 0;
      for (unsigned int l = 0; l < next_codes.size(); ++l)
        n_changed += (next_codes[l] != current_codes[l]);
      if (distributed)
        n_changed = Utilities::MPI::sum(n_changed, comm);
      // In 3D a slip direction may turn without changing the code.
      for (unsigned int j = 0; j < n; ++j)
        if (rows.is_owned(j))
          {
            NodeState<dim> &node   = state.node(j);
            node.status            = proposed[j].status;
            node.slip_direction    = proposed[j].slip_direction;
            node.turning_stiffness = proposed[j].turning_stiffness;
          }
      history.push_back(next_codes);
      history_residual.push_back(std::numeric_limits<double>::infinity());
      return n_changed;
    }



    // The opened band, mirrored about its inner end (see update()): the
    // opened nodes of every rank, the distance of each to the closed set
    // (the minimum over the ranks), then each rank opens the closed nodes
    // it owns within twice that distance of an opened node.
    template <int dim>
    void
    ActiveSetPolicy<dim>::extrapolate_release(
      const std::vector<NodeKinematics<dim>> &nodes,
      const RowPartition                     &rows,
      const std::vector<bool>                &closed,
      std::vector<bool>                      &next)
    {
      const MPI_Comm            comm        = rows.communicator();
      const bool                distributed = rows.is_distributed();
      const unsigned int        n           = nodes.size();
      std::vector<unsigned int> opened, kept;
      for (unsigned int j = 0; j < n; ++j)
        if (!rows.is_owned(j))
          continue;
        else if (closed[j] && !next[j])
          opened.push_back(j);
        else if (next[j])
          kept.push_back(j);
      unsigned int n_kept = kept.size();
      if (distributed)
        {
          n_kept = Utilities::MPI::sum(n_kept, comm);
          std::vector<unsigned int> all;
          for (const auto &part : Utilities::MPI::all_gather(comm, opened))
            all.insert(all.end(), part.begin(), part.end());
          std::sort(all.begin(), all.end());
          opened = all;
        }
      // Mirroring is about one contact edge: with closed nodes on several
      // primary bodies (two rigid tools) the opened band of one body says
      // nothing about the zone of another, and no node is added.
      std::vector<types::global_dof_index> bodies;
      for (const unsigned int j : kept)
        bodies.push_back(nodes[j].partner);
      if (distributed)
        {
          std::vector<types::global_dof_index> all;
          for (const auto &part : Utilities::MPI::all_gather(comm, bodies))
            all.insert(all.end(), part.begin(), part.end());
          bodies = all;
        }
      std::sort(bodies.begin(), bodies.end());
      const bool one_body =
        std::unique(bodies.begin(), bodies.end()) - bodies.begin() <= 1;
      std::vector<unsigned int> also_opened;
      if (n_kept > 0 && one_body)
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
            {
              const unsigned int i = closed_set.nearest(positions[opened[r]]);
              band[r]              = i == numbers::invalid_unsigned_int ?
                                       std::numeric_limits<double>::max() :
                                       positions[opened[r]].distance(positions[i]);
            }
          if (distributed)
            Utilities::MPI::min(band, comm, band);
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
      unsigned int n_also_opened = also_opened.size();
      if (distributed)
        n_also_opened = Utilities::MPI::sum(n_also_opened, comm);
      // Never open the whole zone: keep the plain step then.
      if (n_kept > 0 && n_also_opened < n_kept)
        {
          for (const unsigned int j : also_opened)
            next[j] = false;
          last_update_extrapolated = n_also_opened > 0;
        }
    }



    // The node (of any rank) whose change alone leads to an unseen set,
    // the one with the largest complementarity violation: each rank rates
    // its changed nodes, with the number of nodes (over all ranks) in which
    // each history entry differs from the current set.
    template <int dim>
    std::pair<unsigned int, bool>
    ActiveSetPolicy<dim>::single_change(
      const std::vector<NodeKinematics<dim>> &nodes,
      const NormalEnforcement<dim>           &normal,
      const FrictionModel<dim>               &friction,
      const ContactState<dim>                &state,
      const std::vector<int>                 &current_codes,
      const std::vector<int>                 &next_codes) const
    {
      const RowPartition       &rows        = state.rows();
      const MPI_Comm            comm        = rows.communicator();
      const bool                distributed = rows.is_distributed();
      std::vector<unsigned int> differing(history.size(), 0);
      for (unsigned int i = 0; i < history.size(); ++i)
        for (unsigned int l = 0; l < current_codes.size(); ++l)
          differing[i] += (history[i][l] != current_codes[l]);
      if (distributed)
        Utilities::MPI::sum(differing, comm, differing);

      // (violation, node, 2 if its change alone leads to an unseen set, 1 if
      // only to the set of an earlier equilibrium (history_residual 0, see
      // restart_history()), 0 if to a set seen otherwise).
      std::vector<double> candidates;
      for (unsigned int j = 0, l = 0; j < nodes.size(); ++j)
        {
          if (!rows.is_owned(j))
            continue;
          if (next_codes[l] != current_codes[l])
            {
              const auto [C_n, C_t] =
                complementarity(j, nodes, normal, friction, state);
              bool unseen = true, only_equilibria = true;
              for (unsigned int i = 0; i < history.size(); ++i)
                if (history_counts[i] && history[i][l] == next_codes[l] &&
                    differing[i] ==
                      (history[i][l] != current_codes[l] ? 1u : 0u))
                  {
                    unseen = false;
                    only_equilibria =
                      only_equilibria && history_residual[i] == 0.;
                  }
              candidates.push_back((std::abs(C_n) + C_t.norm()) *
                                   nodes[j].weight);
              candidates.push_back(j);
              candidates.push_back(unseen ? 2. : (only_equilibria ? 1. : 0.));
            }
          ++l;
        }
      if (distributed)
        {
          std::vector<double> all;
          for (const auto &part : Utilities::MPI::all_gather(comm, candidates))
            all.insert(all.end(), part.begin(), part.end());
          candidates = all;
        }
      std::vector<std::pair<double, unsigned int>> violations;
      std::vector<unsigned int>                    unseen, equilibria;
      for (unsigned int c = 0; c + 2 < candidates.size(); c += 3)
        {
          const auto j = static_cast<unsigned int>(candidates[c + 1]);
          violations.emplace_back(candidates[c], j);
          if (candidates[c + 2] > 1.5)
            unseen.push_back(j);
          else if (candidates[c + 2] > 0.5)
            equilibria.push_back(j);
        }
      std::sort(violations.rbegin(), violations.rend());
      // A set not seen yet first; else back to an earlier equilibrium's
      // set, whose iteration may take another path from here.
      for (const auto *allowed : {&unseen, &equilibria})
        for (const auto &[size, j] : violations)
          if (std::find(allowed->begin(), allowed->end(), j) != allowed->end())
            return {j, allowed == &equilibria};
      return {numbers::invalid_unsigned_int, false};
    }



    template <int dim>
    bool
    ActiveSetPolicy<dim>::is_cycling() const
    {
      return cycling;
    }



    template <int dim>
    bool
    ActiveSetPolicy<dim>::revisits_held_set() const
    {
      return revisited_held_set;
    }



    template <int dim>
    double
    ActiveSetPolicy<dim>::complementarity_norm(
      const std::vector<NodeKinematics<dim>> &nodes,
      const NormalEnforcement<dim>           &normal,
      const FrictionModel<dim>               &friction,
      const ContactState<dim>                &state) const
    {
      // The owned nodes' share, summed over the ranks.
      const RowPartition &rows = state.rows();
      double              sum  = 0.;
      for (unsigned int j = 0; j < nodes.size(); ++j)
        {
          if (!nodes[j].paired || !rows.is_owned(j))
            continue;
          const auto [C_n, C_t] =
            complementarity(j, nodes, normal, friction, state);
          // A penalty carries no tangential multiplier: its norm is the
          // departure from the normal law alone.
          const double C_t_squared =
            normal.has_multipliers() ? C_t.norm_square() : 0.;
          sum += (C_n * C_n + C_t_squared) * nodes[j].weight * nodes[j].weight;
        }
      if (rows.is_distributed())
        sum = Utilities::MPI::sum(sum, rows.communicator());
      return std::sqrt(sum);
    }



    template <int dim>
    bool
    ActiveSetPolicy<dim>::touches_search_edge(
      const MortarCoupling<dim> &coupling,
      const ContactState<dim>   &state)
    {
      // Each rank looks at the faces of its own cells, whose nodes it
      // holds; the answer is true if it is on any rank.
      const RowPartition &rows    = state.rows();
      const auto         &surface = coupling.secondary_surface();
      bool                touches = false;
      for (unsigned int f = 0; f < surface.n_faces() && !touches; ++f)
        {
          if (rows.is_distributed() &&
              !surface.face(f).cell->is_locally_owned())
            continue;
          bool any_active = false, any_unpaired = false;
          for (const unsigned int j : surface.face(f).nodes)
            {
              any_active = any_active || state.is_closed(j);
              // A node without measure (on the axis) bounds no search.
              any_unpaired = any_unpaired || (!coupling.row(j).has_partner &&
                                              coupling.row(j).weight > 0.);
            }
          touches = any_active && any_unpaired;
        }
      if (rows.is_distributed())
        touches = Utilities::MPI::max(static_cast<unsigned int>(touches),
                                      rows.communicator()) > 0;
      return touches;
    }

    template class ActiveSetPolicy<2>;
    template class ActiveSetPolicy<3>;
  } // namespace Contact
} // namespace Common
