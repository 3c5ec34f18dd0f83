#include <common/contact/trial_corrections.h>

#include <deal.II/base/exceptions.h>

#include <algorithm>

namespace Common
{
  namespace Contact
  {
    using namespace dealii;

    void
    TrialCorrections::clear()
    {
      corrections.clear();
      index.clear();
    }



    void
    TrialCorrections::add(TrialCorrection &&correction)
    {
      Assert(index.find(correction.dof) == index.end(),
             ExcMessage("A DoF has two trial corrections."));
      index[correction.dof] = corrections.size();
      corrections.push_back(std::move(correction));
    }



    bool
    TrialCorrections::empty() const
    {
      return corrections.empty();
    }



    const std::vector<TrialCorrection> &
    TrialCorrections::all() const
    {
      return corrections;
    }



    const TrialCorrection *
    TrialCorrections::find(const types::global_dof_index dof) const
    {
      const auto it = index.find(dof);
      return it == index.end() ? nullptr : &corrections[it->second];
    }



    void
    TrialCorrections::extend_columns(
      std::vector<types::global_dof_index> &column_dofs,
      FullMatrix<double>                   &matrix,
      Vector<double>                       &rhs) const
    {
      AssertDimension(matrix.n(), column_dofs.size());
      AssertDimension(matrix.m(), rhs.size());
      if (corrections.empty())
        return;
      // The columns to add and, for each corrected column, where its
      // coefficients go.
      std::vector<types::global_dof_index> columns = column_dofs;
      std::vector<std::pair<unsigned int, const TrialCorrection *>> corrected;
      for (unsigned int b = 0; b < column_dofs.size(); ++b)
        if (const TrialCorrection *correction = find(column_dofs[b]))
          {
            corrected.emplace_back(b, correction);
            for (const auto &entry : correction->entries)
              if (std::find(columns.begin(), columns.end(), entry.first) ==
                  columns.end())
                columns.push_back(entry.first);
          }
      if (corrected.empty())
        return;

      FullMatrix<double> extended(matrix.m(), columns.size());
      for (unsigned int a = 0; a < matrix.m(); ++a)
        for (unsigned int b = 0; b < matrix.n(); ++b)
          extended(a, b) = matrix(a, b);
      for (const auto &[b, correction] : corrected)
        for (unsigned int a = 0; a < matrix.m(); ++a)
          {
            const double value = matrix(a, b);
            if (value == 0.)
              continue;
            rhs(a) -= value * correction->inhomogeneity;
            for (const auto &[q, coefficient] : correction->entries)
              {
                const unsigned int position =
                  std::find(columns.begin(), columns.end(), q) -
                  columns.begin();
                extended(a, position) += value * coefficient;
              }
          }
      column_dofs = std::move(columns);
      matrix      = std::move(extended);
    }
  } // namespace Contact
} // namespace Common
