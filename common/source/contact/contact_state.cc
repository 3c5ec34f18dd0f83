#include <common/contact/contact_search.h>
#include <common/contact/contact_state.h>

#include <algorithm>
#include <limits>
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
      return std::count_if(current.begin(),
                           current.end(),
                           [](const NodeState<dim> &s) {
                             return s.status != PointStatus::open;
                           });
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
      // query each (NearestPoints), not a loop over all nodes.
      std::vector<Point<dim>>   positions(n);
      std::vector<unsigned int> paired, closed_at_start, open_at_end;
      bool                      any_closing = false;
      for (unsigned int j = 0; j < n; ++j)
        {
          positions[j] = nodes[j].position;
          any_closing =
            any_closing || (current[j].status != PointStatus::open &&
                            accepted[j].status == PointStatus::open);
          if (!nodes[j].paired)
            continue;
          paired.push_back(j);
          if (accepted[j].status != PointStatus::open)
            closed_at_start.push_back(j);
          if (current[j].status == PointStatus::open)
            open_at_end.push_back(j);
        }
      std::unique_ptr<NearestPoints<dim>> near_paired, near_closed, near_open;
      if (any_closing)
        {
          near_paired = std::make_unique<NearestPoints<dim>>(positions, paired);
          near_closed =
            std::make_unique<NearestPoints<dim>>(positions, closed_at_start);
          near_open =
            std::make_unique<NearestPoints<dim>>(positions, open_at_end);
        }
      // Distance from node j to the nearest other node of a set.
      const auto distance_to = [&positions](const NearestPoints<dim> &set,
                                            const unsigned int        j) {
        const unsigned int i = set.nearest(positions[j], j);
        return i == numbers::invalid_unsigned_int ?
                 std::numeric_limits<double>::max() :
                 positions[j].distance(positions[i]);
      };

      for (unsigned int j = 0; j < n; ++j)
        {
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
                  const double spacing = distance_to(*near_paired, j);
                  const double d_old   = distance_to(*near_closed, j);
                  const double d_new   = distance_to(*near_open, j);
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

    template class ContactState<2>;
    template class ContactState<3>;
  } // namespace Contact
} // namespace Common
