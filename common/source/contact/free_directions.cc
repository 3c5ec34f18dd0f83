#include <common/contact/free_directions.h>

namespace Common
{
  namespace Contact
  {
    using namespace dealii;

    namespace
    {
      /** Unit vector along coordinate direction d. */
      template <int dim>
      Tensor<1, dim>
      unit_vector(const unsigned int d)
      {
        Tensor<1, dim> e;
        e[d] = 1.;
        return e;
      }
    } // namespace



    template <int dim>
    std::vector<Tensor<1, dim>>
    tangent_basis(const Tensor<1, dim> &n)
    {
      std::vector<Tensor<1, dim>> basis;
      if constexpr (dim == 2)
        basis.push_back(Tensor<1, dim>({n[1], -n[0]}));
      else
        {
          // The coordinate direction least aligned with n, made orthogonal
          // to it, and the cross product.
          unsigned int d = 0;
          for (unsigned int e = 1; e < dim; ++e)
            if (std::abs(n[e]) < std::abs(n[d]))
              d = e;
          Tensor<1, dim> t1 = unit_vector<dim>(d);
          t1 -= (t1 * n) * n;
          t1 /= t1.norm();
          basis.push_back(t1);
          basis.push_back(cross_product_3d(n, t1));
        }
      return basis;
    }



    template <int dim>
    FreeDirections<dim>::FreeDirections(
      const std::vector<Tensor<1, dim>> &normals)
      : normals(normals)
      , tangents(normals.size())
      , free_normally(normals.size(), true)
      , fixed_components(normals.size())
    {
      for (unsigned int j = 0; j < normals.size(); ++j)
        tangents[j] = tangent_basis(normals[j]);
    }



    template <int dim>
    void
    FreeDirections<dim>::update_normals(
      const std::vector<Tensor<1, dim>> &new_normals)
    {
      AssertDimension(new_normals.size(), size());
      normals = new_normals;
      for (unsigned int j = 0; j < size(); ++j)
        fix_components(j, fixed_components[j]);
    }



    template <int dim>
    void
    FreeDirections<dim>::fix_components(const unsigned int           j,
                                        const std::array<bool, dim> &fixed)
    {
      fixed_components[j]     = fixed;
      const Tensor<1, dim> &n = normals[j];
      // The tangent directions w with w_d = 0 for every fixed d: the tangent
      // plane minus the span of the fixed unit vectors' tangential parts
      // (Gram-Schmidt).
      std::vector<Tensor<1, dim>> fixed_tangential;
      for (unsigned int d = 0; d < dim; ++d)
        if (fixed[d])
          {
            Tensor<1, dim> w = unit_vector<dim>(d);
            w                = w - (w * n) * n;
            for (const auto &q : fixed_tangential)
              w -= (w * q) * q;
            if (w.norm() > 1e-8)
              fixed_tangential.push_back(w / w.norm());
          }
      std::vector<Tensor<1, dim>> free;
      for (Tensor<1, dim> b : tangent_basis(n))
        {
          for (const auto &q : fixed_tangential)
            b -= (b * q) * q;
          for (const auto &q : free)
            b -= (b * q) * q;
          if (b.norm() > 1e-8)
            free.push_back(b / b.norm());
        }
      tangents[j] = free;
      // A normal condition acts on the node's own displacement through a
      // free component with a share of the normal (the threshold of
      // DualLagrangeEnforcement::add_constraints()).
      free_normally[j] = false;
      for (unsigned int d = 0; d < dim; ++d)
        free_normally[j] =
          free_normally[j] || (!fixed[d] && std::abs(n[d]) >= 1e-6);
    }



    template <int dim>
    void
    FreeDirections<dim>::fix_constrained_components(
      const ContactSurface<dim>       &surface,
      const AffineConstraints<double> &constraints)
    {
      AssertDimension(surface.n_nodes(), size());
      for (unsigned int j = 0; j < size(); ++j)
        {
          std::array<bool, dim> fixed;
          for (unsigned int d = 0; d < dim; ++d)
            fixed[d] = constraints.is_constrained(surface.node(j).dofs[d]);
          fix_components(j, fixed);
        }
    }



    template <int dim>
    unsigned int
    FreeDirections<dim>::size() const
    {
      return normals.size();
    }



    template <int dim>
    const Tensor<1, dim> &
    FreeDirections<dim>::normal(const unsigned int j) const
    {
      return normals[j];
    }



    template <int dim>
    const std::vector<Tensor<1, dim>> &
    FreeDirections<dim>::free_tangents(const unsigned int j) const
    {
      return tangents[j];
    }



    template <int dim>
    bool
    FreeDirections<dim>::normally_free(const unsigned int j) const
    {
      return free_normally[j];
    }



    template <int dim>
    Tensor<1, dim>
    FreeDirections<dim>::free_tangential_part(const unsigned int    j,
                                              const Tensor<1, dim> &x) const
    {
      Tensor<1, dim> result;
      for (const auto &b : tangents[j])
        result += (x * b) * b;
      return result;
    }

    template std::vector<Tensor<1, 2>>
    tangent_basis(const Tensor<1, 2> &);
    template std::vector<Tensor<1, 3>>
    tangent_basis(const Tensor<1, 3> &);
    template class FreeDirections<2>;
    template class FreeDirections<3>;
  } // namespace Contact
} // namespace Common
