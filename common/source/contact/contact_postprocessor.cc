#include <common/contact/contact_postprocessor.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>

#include <algorithm>
#include <fstream>
#include <iomanip>

namespace Common
{
  namespace Contact
  {
    using namespace dealii;

    template <int dim>
    Tensor<1, dim>
    tangent_of(const Tensor<1, dim> &n)
    {
      Tensor<1, dim> t;
      if constexpr (dim == 2)
        {
          t[0] = n[1];
          t[1] = -n[0];
        }
      else
        {
          const Tensor<1, dim> e =
            (std::abs(n[0]) < 0.9 ? Tensor<1, dim>({1., 0., 0.}) :
                                    Tensor<1, dim>({0., 1., 0.}));
          t = e - (e * n) * n;
          t /= t.norm();
        }
      return t;
    }



    template <int dim>
    std::vector<ContactPointResult<dim>>
    contact_profile(const MortarCoupling<dim>           &coupling,
                    const ContactEnforcement<dim>       &enforcement,
                    const TrilinosWrappers::MPI::Vector &u,
                    const TrilinosWrappers::MPI::Vector &bulk_residual,
                    const unsigned int                   axis)
    {
      // Each rank evaluates the paired nodes it owns; every rank gets all
      // of them, in the order of the nodes, before the sort along the axis
      // (the serial order also where positions tie).
      std::vector<ContactPointResult<dim>> profile;
      const auto         &surface = coupling.secondary_surface();
      const RowPartition &rows    = enforcement.rows();
      for (unsigned int j = 0; j < coupling.n_rows(); ++j)
        {
          const MortarRow<dim> &row = coupling.row(j);
          if (!row.has_partner || !rows.is_owned(j))
            continue;
          const auto          &node = surface.node(j);
          const Tensor<1, dim> t    = tangent_of(row.normal);
          Tensor<1, dim>       r;
          for (unsigned int c = 0; c < dim; ++c)
            r[c] = bulk_residual(node.dofs[c]);

          ContactPointResult<dim> result;
          result.node     = j;
          result.position = node.reference_position;
          result.pressure = enforcement.pressure(j);
          // The contact force on node j is -r_j: its tangential part per
          // unit area is the traction on the secondary surface.
          const Tensor<1, dim> r_tangential = r - (r * row.normal) * row.normal;
          result.normal                     = row.normal;
          result.tangential_traction_vector = enforcement.is_active(j) ?
                                                -r_tangential / row.weight :
                                                Tensor<1, dim>();
          result.tangential_traction =
            enforcement.is_active(j) ? -(r * t) / row.weight : 0.;
          result.slip_vector = enforcement.accumulated_slip(j);
          result.slip        = result.slip_vector * t;
          result.relative_displacement_vector =
            coupling.relative_displacement(j, u);
          result.relative_displacement =
            result.relative_displacement_vector * t;
          result.gap    = coupling.weighted_gap(j, u) / row.weight;
          result.status = to_string(enforcement.status(j));
          profile.push_back(result);
        }
      if (rows.is_distributed())
        {
          // Node, pressure, tangential traction, slip, relative
          // displacement, gap, status, then the normal, traction, slip and
          // relative displacement vectors.
          constexpr unsigned int stride = 7 + 4 * dim;
          std::vector<double>    local;
          for (const auto &p : profile)
            {
              local.insert(local.end(),
                           {static_cast<double>(p.node),
                            p.pressure,
                            p.tangential_traction,
                            p.slip,
                            p.relative_displacement,
                            p.gap,
                            static_cast<double>(enforcement.status(p.node))});
              for (const auto *v : {&p.normal,
                                    &p.tangential_traction_vector,
                                    &p.slip_vector,
                                    &p.relative_displacement_vector})
                for (unsigned int c = 0; c < dim; ++c)
                  local.push_back((*v)[c]);
            }
          profile.clear();
          for (const auto &part :
               Utilities::MPI::all_gather(rows.communicator(), local))
            for (unsigned int i = 0; i + stride <= part.size(); i += stride)
              {
                ContactPointResult<dim> result;
                result.node     = static_cast<unsigned int>(part[i]);
                result.position = surface.node(result.node).reference_position;
                result.pressure = part[i + 1];
                result.tangential_traction   = part[i + 2];
                result.slip                  = part[i + 3];
                result.relative_displacement = part[i + 4];
                result.gap                   = part[i + 5];
                result.status                = to_string(
                  static_cast<PointStatus>(static_cast<int>(part[i + 6])));
                unsigned int k = i + 7;
                for (auto *v : {&result.normal,
                                &result.tangential_traction_vector,
                                &result.slip_vector,
                                &result.relative_displacement_vector})
                  for (unsigned int c = 0; c < dim; ++c)
                    (*v)[c] = part[k++];
                profile.push_back(result);
              }
          std::sort(profile.begin(),
                    profile.end(),
                    [](const auto &a, const auto &b) {
                      return a.node < b.node;
                    });
        }
      std::sort(profile.begin(),
                profile.end(),
                [axis](const auto &a, const auto &b) {
                  return a.position[axis] < b.position[axis];
                });
      return profile;
    }



    template <int dim>
    Tensor<1, dim>
    total_contact_force(const MortarCoupling<dim>     &coupling,
                        const ContactEnforcement<dim> &enforcement)
    {
      // The owned nodes' share, summed over the ranks.
      const RowPartition &rows = enforcement.rows();
      Tensor<1, dim>      force;
      for (unsigned int j = 0; j < coupling.n_rows(); ++j)
        if (rows.is_owned(j))
          force -= enforcement.pressure(j) * coupling.row(j).weight *
                   coupling.row(j).normal;
      if (enforcement.has_friction())
        for (unsigned int j = 0; j < coupling.n_rows(); ++j)
          if (rows.is_owned(j))
            force +=
              coupling.row(j).weight * enforcement.tangential_traction(j);
      if (rows.is_distributed())
        force = Utilities::MPI::sum(force, rows.communicator());
      return force;
    }



    template <int dim>
    double
    contact_extent(const std::vector<ContactPointResult<dim>> &profile,
                   const unsigned int                          axis)
    {
      if (profile.empty())
        return 0.;
      int last = -1;
      for (unsigned int i = 0; i < profile.size(); ++i)
        if (profile[i].pressure > 0.)
          last = i;
      const double x0 = profile[0].position[axis];
      if (last < 0)
        return 0.;
      const double x_last = profile[last].position[axis];
      if (last + 1 >= static_cast<int>(profile.size()) || last == 0)
        return x_last - x0;
      const double x_next = profile[last + 1].position[axis];
      const double x_prev = profile[last - 1].position[axis];
      const double q_last = std::pow(profile[last].pressure, 2);
      const double q_prev = std::pow(profile[last - 1].pressure, 2);
      double       edge   = x_last;
      if (q_prev > q_last)
        edge = x_last + q_last * (x_last - x_prev) / (q_prev - q_last);
      return std::clamp(edge, x_last, x_next) - x0;
    }



    template <int dim>
    std::vector<
      std::pair<std::string, std::map<types::global_dof_index, double>>>
    contact_nodal_fields(const MortarCoupling<dim>     &coupling,
                         const ContactEnforcement<dim> &enforcement)
    {
      std::vector<
        std::pair<std::string, std::map<types::global_dof_index, double>>>
        fields{{"contact_pressure", {}},
               {"contact_status", {}},
               {"tangential_traction", {}},
               {"contact_slip", {}}};
      for (unsigned int j = 0; j < coupling.n_rows(); ++j)
        {
          if (!enforcement.rows().is_held(j))
            continue;
          const types::global_dof_index dof =
            coupling.secondary_surface().node(j).dofs[0];
          const Tensor<1, dim> t     = tangent_of(coupling.row(j).normal);
          const auto           along = [&t](const Tensor<1, dim> &x) {
            return dim == 2 ? x * t : x.norm();
          };
          fields[0].second[dof] = enforcement.pressure(j);
          fields[1].second[dof] = static_cast<double>(enforcement.status(j));
          fields[2].second[dof] = along(enforcement.tangential_traction(j));
          fields[3].second[dof] = along(enforcement.accumulated_slip(j));
        }
      return fields;
    }



    template <int dim>
    double
    stick_extent(const std::vector<ContactPointResult<dim>> &profile,
                 const unsigned int                          axis)
    {
      unsigned int i = 0;
      while (i < profile.size() && profile[i].status == "open")
        ++i;
      if (i == profile.size() || profile[i].status != "stick")
        return 0.;
      while (i + 1 < profile.size() && profile[i + 1].status == "stick")
        ++i;
      const double x0 = profile[0].position[axis];
      if (i + 1 == profile.size())
        return profile[i].position[axis] - x0;
      // Every closed node sticks: the stick zone is the contact zone.
      if (profile[i + 1].status == "open")
        return contact_extent(profile, axis);
      return 0.5 * (profile[i].position[axis] + profile[i + 1].position[axis]) -
             x0;
    }



    template <int dim>
    double
    pressure_l2_error(
      const MortarCoupling<dim>                       &coupling,
      const ContactEnforcement<dim>                   &enforcement,
      const std::function<double(const Point<dim> &)> &reference,
      double                                          &reference_norm)
    {
      const auto           &surface = coupling.secondary_surface();
      const QGauss<dim - 1> quadrature(surface.base_element().degree + 4);
      std::vector<double>   N;
      // The faces of each rank's own cells (whose nodes it holds), summed
      // over the ranks.
      const RowPartition &rows     = enforcement.rows();
      double              error_sq = 0., reference_sq = 0.;
      for (unsigned int f = 0; f < surface.n_faces(); ++f)
        {
          const auto &face = surface.face(f);
          if (rows.is_distributed() && !face.cell->is_locally_owned())
            continue;
          for (unsigned int q = 0; q < quadrature.size(); ++q)
            {
              surface.shape_values(f, quadrature.point(q), N);
              double     p_h = 0.;
              Point<dim> x;
              for (unsigned int a = 0; a < N.size(); ++a)
                {
                  p_h += N[a] * enforcement.pressure(face.nodes[a]);
                  x += N[a] * surface.node(face.nodes[a]).reference_position;
                }
              const double JxW =
                surface.jacobian(f, quadrature.point(q)) * quadrature.weight(q);
              const double p_ref = reference(x);
              error_sq += std::pow(p_h - p_ref, 2) * JxW;
              reference_sq += p_ref * p_ref * JxW;
            }
        }
      if (rows.is_distributed())
        {
          std::vector<double> sums{error_sq, reference_sq};
          Utilities::MPI::sum(sums, rows.communicator(), sums);
          error_sq     = sums[0];
          reference_sq = sums[1];
        }
      reference_norm = std::sqrt(reference_sq);
      return std::sqrt(error_sq);
    }



    template <int dim>
    void
    write_profile_csv(const std::string                          &filename,
                      const std::vector<ContactPointResult<dim>> &profile,
                      const unsigned int                          axis)
    {
      std::ofstream out(filename);
      AssertThrow(out, ExcMessage("Cannot write " + filename));
      out << "x,pressure,tangential_traction,slip,relative_displacement,gap,"
             "status\n";
      out << std::setprecision(8);
      for (const auto &p : profile)
        {
          AssertThrow(std::isfinite(p.pressure) &&
                        std::isfinite(p.tangential_traction) &&
                        std::isfinite(p.slip) &&
                        std::isfinite(p.relative_displacement) &&
                        std::isfinite(p.gap),
                      ExcMessage("Contact profile holds a non-finite value."));
          out << p.position[axis] << ',' << p.pressure << ','
              << p.tangential_traction << ',' << p.slip << ','
              << p.relative_displacement << ',' << p.gap << ',' << p.status
              << '\n';
        }
    }

    template <int dim>
    std::vector<ContactPointResult<2>>
    plane_section(const std::vector<ContactPointResult<dim>> &profile,
                  const double                                z,
                  const double                                length_scale)
    {
      const auto in_plane = [](const Tensor<1, dim> &v) {
        return Tensor<1, 2>({v[0], v[1]});
      };
      std::vector<ContactPointResult<2>> section;
      for (const auto &p : profile)
        if (dim == 2 ||
            std::abs(p.position[dim - 1] - z) <= 1e-8 * length_scale)
          {
            ContactPointResult<2> q;
            q.node     = p.node;
            q.position = Point<2>(p.position[0], p.position[1]);
            q.pressure = p.pressure;
            q.normal   = in_plane(p.normal);
            q.tangential_traction_vector =
              in_plane(p.tangential_traction_vector);
            q.slip_vector = in_plane(p.slip_vector);
            q.relative_displacement_vector =
              in_plane(p.relative_displacement_vector);
            q.gap                   = p.gap;
            q.status                = p.status;
            q.tangential_traction   = p.tangential_traction;
            q.slip                  = p.slip;
            q.relative_displacement = p.relative_displacement;
            if (dim == 3)
              {
                Tensor<1, 2> t({q.normal[1], -q.normal[0]});
                if (t.norm() > 0.)
                  t /= t.norm();
                q.tangential_traction   = q.tangential_traction_vector * t;
                q.slip                  = q.slip_vector * t;
                q.relative_displacement = q.relative_displacement_vector * t;
              }
            section.push_back(q);
          }
      return section;
    }



#define INSTANTIATE(dim)                                                       \
  template Tensor<1, dim> tangent_of(const Tensor<1, dim> &);                  \
  template std::vector<                                                        \
    std::pair<std::string, std::map<types::global_dof_index, double>>>         \
                  contact_nodal_fields(const MortarCoupling<dim> &,            \
                                       const ContactEnforcement<dim> &);       \
  template double stick_extent(const std::vector<ContactPointResult<dim>> &,   \
                               const unsigned int);                            \
  template std::vector<ContactPointResult<dim>> contact_profile(               \
    const MortarCoupling<dim> &,                                               \
    const ContactEnforcement<dim> &,                                           \
    const TrilinosWrappers::MPI::Vector &,                                     \
    const TrilinosWrappers::MPI::Vector &,                                     \
    const unsigned int);                                                       \
  template Tensor<1, dim> total_contact_force(                                 \
    const MortarCoupling<dim> &,                                               \
    const ContactEnforcement<dim> &);                                          \
  template double contact_extent(const std::vector<ContactPointResult<dim>> &, \
                                 const unsigned int);                          \
  template double pressure_l2_error(                                           \
    const MortarCoupling<dim> &,                                               \
    const ContactEnforcement<dim> &,                                           \
    const std::function<double(const Point<dim> &)> &,                         \
    double &);                                                                 \
  template std::vector<ContactPointResult<2>> plane_section(                   \
    const std::vector<ContactPointResult<dim>> &,                              \
    const double,                                                              \
    const double);                                                             \
  template void write_profile_csv(                                             \
    const std::string &,                                                       \
    const std::vector<ContactPointResult<dim>> &,                              \
    const unsigned int);
    INSTANTIATE(2)
    INSTANTIATE(3)
#undef INSTANTIATE
  } // namespace Contact
} // namespace Common
