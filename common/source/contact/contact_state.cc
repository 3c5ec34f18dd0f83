#include <common/contact/contact_search.h>
#include <common/contact/contact_state.h>

#include <deal.II/base/mpi.h>

#include <algorithm>
#include <array>
#include <limits>
#include <map>
#include <memory>

namespace Common
{
  namespace Contact
  {
    using namespace dealii;

    std::string
    to_string(const PointStatus status)
    {
      switch (status)
        {
          case PointStatus::open:
            return "open";
          case PointStatus::stick:
            return "stick";
          default:
            return "slip";
        }
    }



    template <int dim>
    ContactState<dim>::ContactState(const FreeDirections<dim> &directions)
      : free_directions(directions)
      , current(directions.size())
      , accepted(directions.size())
      , accepted_relative(directions.size())
      , slip_accumulated(directions.size())
    {}



    template <int dim>
    unsigned int
    ContactState<dim>::n_nodes() const
    {
      return current.size();
    }



    template <int dim>
    const FreeDirections<dim> &
    ContactState<dim>::directions() const
    {
      return free_directions;
    }



    template <int dim>
    void
    ContactState<dim>::distribute(const RowPartition &rows)
    {
      partition = rows;
    }



    template <int dim>
    const RowPartition &
    ContactState<dim>::rows() const
    {
      return partition;
    }



    // Owners send, for each ghost row a rank holds, the node's status,
    // slip direction and turning stiffness: 2 + dim numbers per row after
    // its index.
    template <int dim>
    void
    ContactState<dim>::update_ghosts()
    {
      if (!partition.is_distributed())
        return;
      std::map<unsigned int, std::vector<double>> send;
      for (const auto &[rank, rows] : partition.ghost_holders())
        {
          std::vector<double> &data = send[rank];
          data.reserve(rows.size() * (3 + dim));
          for (const unsigned int j : rows)
            {
              data.push_back(j);
              data.push_back(static_cast<double>(current[j].status));
              data.push_back(current[j].turning_stiffness);
              for (unsigned int d = 0; d < dim; ++d)
                data.push_back(current[j].slip_direction[d]);
            }
        }
      const auto received =
        Utilities::MPI::some_to_some(partition.communicator(), send);
      for (const auto &[rank, data] : received)
        for (unsigned int i = 0; i + 3 + dim <= data.size(); i += 3 + dim)
          {
            const unsigned int j = static_cast<unsigned int>(data[i]);
            Assert(partition.is_held(j) && !partition.is_owned(j),
                   ExcInternalError());
            current[j].status =
              static_cast<PointStatus>(static_cast<int>(data[i + 1]));
            current[j].turning_stiffness = data[i + 2];
            for (unsigned int d = 0; d < dim; ++d)
              current[j].slip_direction[d] = data[i + 3 + d];
          }
    }



    template <int dim>
    const NodeState<dim> &
    ContactState<dim>::node(const unsigned int j) const
    {
      return current[j];
    }



    template <int dim>
    NodeState<dim> &
    ContactState<dim>::node(const unsigned int j)
    {
      return current[j];
    }



    template <int dim>
    const NodeState<dim> &
    ContactState<dim>::accepted_node(const unsigned int j) const
    {
      return accepted[j];
    }



    template <int dim>
    bool
    ContactState<dim>::is_closed(const unsigned int j) const
    {
      return current[j].status != PointStatus::open;
    }



    template <int dim>
    unsigned int
    ContactState<dim>::n_closed() const
    {
      unsigned int n = 0;
      for (unsigned int j = 0; j < current.size(); ++j)
        n += (partition.is_owned(j) && current[j].status != PointStatus::open);
      return n;
    }



    template <int dim>
    const Tensor<1, dim> &
    ContactState<dim>::accepted_relative_displacement(
      const unsigned int j) const
    {
      return accepted_relative[j];
    }



    template <int dim>
    const Tensor<1, dim> &
    ContactState<dim>::accumulated_slip(const unsigned int j) const
    {
      return slip_accumulated[j];
    }



    template <int dim>
    Tensor<1, dim>
    ContactState<dim>::slip_increment(
      const unsigned int    j,
      const Tensor<1, dim> &relative_displacement) const
    {
      return free_directions.free_tangential_part(j,
                                                  relative_displacement -
                                                    accepted_relative[j]);
    }



    template <int dim>
    void
    ContactState<dim>::reset(const std::vector<PointStatus> &status)
    {
      AssertDimension(status.size(), n_nodes());
      for (unsigned int j = 0; j < n_nodes(); ++j)
        {
          current[j]        = NodeState<dim>();
          current[j].status = status[j];
        }
      accepted = current;
      std::fill(accepted_relative.begin(),
                accepted_relative.end(),
                Tensor<1, dim>());
      std::fill(slip_accumulated.begin(),
                slip_accumulated.end(),
                Tensor<1, dim>());
    }



    template <int dim>
    void
    ContactState<dim>::commit(const std::vector<NodeKinematics<dim>> &nodes)
    {
      const unsigned int n = n_nodes();
      AssertDimension(nodes.size(), n);

      // A node that closed during the step needs the distances to the
      // nearest other paired node, to the nearest one closed at the start
      // and to the nearest one open at the end of the step: one R-tree
      // query each (NearestPoints) over the nodes this rank owns, not a
      // loop over all nodes, and the minimum over the ranks.
      std::vector<Point<dim>>   positions(n);
      std::vector<unsigned int> paired, closed_at_start, open_at_end;
      std::vector<unsigned int> closing;
      for (unsigned int j = 0; j < n; ++j)
        {
          positions[j] = nodes[j].position;
          if (partition.is_held(j) && current[j].status != PointStatus::open &&
              accepted[j].status == PointStatus::open)
            closing.push_back(j);
          if (!nodes[j].paired || !partition.is_owned(j))
            continue;
          paired.push_back(j);
          if (accepted[j].status != PointStatus::open)
            closed_at_start.push_back(j);
          if (current[j].status == PointStatus::open)
            open_at_end.push_back(j);
        }
      // Every rank's closing nodes, in increasing order.
      std::vector<unsigned int> queries = closing;
      if (partition.is_distributed())
        {
          queries.clear();
          for (const auto &part :
               Utilities::MPI::all_gather(partition.communicator(), closing))
            queries.insert(queries.end(), part.begin(), part.end());
          std::sort(queries.begin(), queries.end());
          queries.erase(std::unique(queries.begin(), queries.end()),
                        queries.end());
        }
      // Per query: spacing, distance to the closed set at the start and
      // to the open set at the end.
      std::map<unsigned int, std::array<double, 3>> distances;
      if (!queries.empty())
        {
          const NearestPoints<dim> near_paired(positions, paired);
          const NearestPoints<dim> near_closed(positions, closed_at_start);
          const NearestPoints<dim> near_open(positions, open_at_end);
          // Distance from node j to the nearest other node of a set.
          const auto distance_to = [&positions](const NearestPoints<dim> &set,
                                                const unsigned int        j) {
            const unsigned int i = set.nearest(positions[j], j);
            return i == numbers::invalid_unsigned_int ?
                     std::numeric_limits<double>::max() :
                     positions[j].distance(positions[i]);
          };
          std::vector<double> local(3 * queries.size());
          for (unsigned int q = 0; q < queries.size(); ++q)
            {
              local[3 * q]     = distance_to(near_paired, queries[q]);
              local[3 * q + 1] = distance_to(near_closed, queries[q]);
              local[3 * q + 2] = distance_to(near_open, queries[q]);
            }
          std::vector<double> global = local;
          if (partition.is_distributed())
            Utilities::MPI::min(local, partition.communicator(), global);
          for (unsigned int q = 0; q < queries.size(); ++q)
            distances[queries[q]] = {
              {global[3 * q], global[3 * q + 1], global[3 * q + 2]}};
        }

      for (unsigned int j = 0; j < n; ++j)
        {
          if (!partition.is_held(j))
            continue;
          const Tensor<1, dim> &relative = nodes[j].relative_displacement;
          if (current[j].status != PointStatus::open)
            {
              const Tensor<1, dim> increment = slip_increment(j, relative);
              double               fraction  = 1.;
              if (accepted[j].status == PointStatus::open)
                {
                  // Closed during the step: credit the part of the step
                  // after the contact edge passed the node, with the edge
                  // midway between the last closed and first open nodes at
                  // the start (old) and end (new) of the step.
                  const auto  &d       = distances.at(j);
                  const double spacing = d[0];
                  const double d_old   = d[1];
                  const double d_new   = d[2];
                  if (d_old < std::numeric_limits<double>::max() &&
                      d_new < std::numeric_limits<double>::max() &&
                      d_old + d_new > spacing)
                    fraction = std::clamp((d_new - 0.5 * spacing) /
                                            (d_old + d_new - spacing),
                                          0.,
                                          1.);
                  else
                    fraction = 0.5;
                }
              slip_accumulated[j] += fraction * increment;
            }
          accepted_relative[j] = relative;
        }
      accepted = current;
    }



    template <int dim>
    void
    ContactState<dim>::restore()
    {
      current = accepted;
    }



    template <int dim>
    void
    ContactState<dim>::rebase(
      const std::vector<Tensor<1, dim>> &accepted_relative_displacements)
    {
      AssertDimension(accepted_relative_displacements.size(), n_nodes());
      for (unsigned int j = 0; j < n_nodes(); ++j)
        if (partition.is_held(j))
          accepted_relative[j] = accepted_relative_displacements[j];
    }

    template class ContactState<2>;
    template class ContactState<3>;
  } // namespace Contact
} // namespace Common
