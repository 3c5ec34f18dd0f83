#include <common/contact/contact_state.h>

#include <algorithm>
#include <limits>

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
                  const Point<dim> &x     = nodes[j].position;
                  double            d_old = std::numeric_limits<double>::max();
                  double            d_new = d_old, spacing = d_old;
                  for (unsigned int i = 0; i < n; ++i)
                    {
                      if (i == j || !nodes[i].paired)
                        continue;
                      const double d = x.distance(nodes[i].position);
                      spacing        = std::min(spacing, d);
                      if (accepted[i].status != PointStatus::open)
                        d_old = std::min(d_old, d);
                      if (current[i].status == PointStatus::open)
                        d_new = std::min(d_new, d);
                    }
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
