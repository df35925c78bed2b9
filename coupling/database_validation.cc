#include "coupling/database_validation.h"

#include <Eigen/Eigenvalues>

#include <cmath>
#include <limits>
#include <map>
#include <stdexcept>

namespace compax::coupling
{
  namespace
  {
    dealii::SymmetricTensor<2, 3>
    to_deal(const Eigen::Matrix3d &m)
    {
      dealii::SymmetricTensor<2, 3> t;
      for (unsigned int i = 0; i < 3; ++i)
        for (unsigned int j = i; j < 3; ++j)
          t[i][j] = 0.5 * (m(i, j) + m(j, i));
      return t;
    }

    dem::Vector6d
    to_voigt(const dealii::SymmetricTensor<2, 3> &t)
    {
      dem::Vector6d v;
      v << t[0][0], t[1][1], t[2][2], t[1][2], t[0][2], t[0][1];
      return v;
    }

    /// Frobenius norm squared of a Voigt stress.
    double
    norm2(const dem::Vector6d &s)
    {
      return s[0] * s[0] + s[1] * s[1] + s[2] * s[2]
             + 2.0 * (s[3] * s[3] + s[4] * s[4] + s[5] * s[5]);
    }

    /// Rows of each (branch, path), in order of first appearance.
    struct Paths
    {
      std::vector<std::pair<int, std::string>>                        keys;
      std::map<std::pair<int, std::string>, std::vector<std::size_t>> rows;
    };

    Paths
    group(const RveDatabase &db)
    {
      Paths g;
      for (std::size_t r = 0; r < db.rows.size(); ++r)
        {
          const auto key = std::make_pair(db.rows[r].branch, db.rows[r].path);
          auto      &v   = g.rows[key];
          if (v.empty())
            g.keys.push_back(key);
          v.push_back(r);
        }
      return g;
    }

    struct Sums
    {
      double      ds2 = 0, s2 = 0, dp2 = 0, dq2 = 0, pq2 = 0;
      std::size_t n = 0;
    };

    Sums
    sums(const RveDatabase              &ref,
         const RveDatabase              &other,
         const std::vector<std::size_t> &a,
         const std::vector<std::size_t> &b)
    {
      Sums s;
      s.n = std::min(a.size(), b.size());
      for (std::size_t k = 0; k < s.n; ++k)
        {
          const dem::Vector6d   &x  = ref.rows[a[k]].stress;
          const dem::Vector6d   &y  = other.rows[b[k]].stress;
          const StressInvariants ix = invariants(x), iy = invariants(y);
          s.ds2 += norm2(y - x);
          s.s2 += norm2(x);
          s.dp2 += (iy.p - ix.p) * (iy.p - ix.p);
          s.dq2 += (iy.q - ix.q) * (iy.q - ix.q);
          s.pq2 += ix.p * ix.p + ix.q * ix.q;
        }
      return s;
    }

    double
    ratio(const double a, const double b)
    {
      return b > 0.0
               ? std::sqrt(a / b)
               : (a > 0.0 ? std::numeric_limits<double>::infinity() : 0.0);
    }

    /// ln of a symmetric positive definite matrix.
    Eigen::Matrix3d
    log_spd(const Eigen::Matrix3d &m)
    {
      Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(0.5
                                                        * (m + m.transpose()));
      return es.eigenvectors()
             * es.eigenvalues().array().log().matrix().asDiagonal()
             * es.eigenvectors().transpose();
    }

    Eigen::Matrix3d
    exp_sym(const Eigen::Matrix3d &m)
    {
      Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(m);
      return es.eigenvectors()
             * es.eigenvalues().array().exp().matrix().asDiagonal()
             * es.eigenvectors().transpose();
    }
  } // namespace

  std::vector<dem::Vector6d>
  drive_along_database(const RveDatabase &db, const fem::MaterialModel &law)
  {
    const unsigned int               nh = law.n_history();
    std::vector<std::vector<double>> history(db.rows.size(),
                                             std::vector<double>(nh));
    std::vector<dem::Vector6d>       stress(db.rows.size());
    std::vector<double>              work(nh), trial(nh);
    fem::MaterialResponse            response;
    for (std::size_t r = 0; r < db.rows.size(); ++r)
      {
        const DatabaseRow &row = db.rows[r];
        if (row.parent < 0)
          {
            law.initialize(row.relative_density,
                           dealii::make_array_view(history[r]));
            stress[r] = to_voigt(law.stress(dealii::make_array_view(
              static_cast<const std::vector<double> &>(history[r]))));
            continue;
          }
        if (static_cast<std::size_t>(row.parent) >= r)
          throw std::runtime_error("continuum law along the database: row "
                                   + std::to_string(r)
                                   + " comes before its parent");
        const Eigen::Matrix3d F_inc
          = row.deformation * db.rows[row.parent].deformation.inverse();
        const Eigen::Matrix3d eps = log_spd(F_inc);
        bool                  ok  = false;
        for (int n = 1; n <= 64 && !ok; n *= 2)
          {
            fem::MaterialIncrement inc;
            inc.strain_increment     = to_deal(eps / n);
            const Eigen::Matrix3d Fs = exp_sym(eps / n);
            for (unsigned int i = 0; i < 3; ++i)
              for (unsigned int j = 0; j < 3; ++j)
                inc.deformation_increment[i][j] = Fs(i, j);
            work = history[row.parent];
            ok   = true;
            for (int k = 0; k < n && ok; ++k)
              {
                ok = law.evaluate(inc,
                                  dealii::make_array_view(
                                    static_cast<const std::vector<double> &>(
                                      work)),
                                  dealii::make_array_view(trial),
                                  response);
                work.swap(trial);
              }
          }
        if (!ok)
          throw std::runtime_error("continuum law along the database: the "
                                   + law.name() + " law cannot follow the "
                                   + row.path + " increment of row "
                                   + std::to_string(r));
        history[r] = work;
        stress[r]  = to_voigt(response.stress);
      }
    return stress;
  }

  RveDatabase
  with_stresses(RveDatabase db, const std::vector<dem::Vector6d> &stress)
  {
    if (stress.size() != db.rows.size())
      throw std::invalid_argument("with_stresses: one stress per row needed");
    for (std::size_t r = 0; r < db.rows.size(); ++r)
      db.rows[r].stress = stress[r];
    return db;
  }

  std::vector<PathError>
  path_errors(const RveDatabase &reference, const RveDatabase &other)
  {
    const Paths            a = group(reference), b = group(other);
    std::vector<PathError> out;
    for (const auto &key : a.keys)
      {
        const auto it = b.rows.find(key);
        if (it == b.rows.end())
          continue;
        const auto &ra = a.rows.at(key);
        const Sums  s  = sums(reference, other, ra, it->second);
        out.push_back({key.first,
                       key.second,
                       is_training_path(key.second),
                       reference.rows[ra.front()].relative_density,
                       s.n,
                       ratio(s.ds2, s.s2),
                       ratio(s.dp2, s.pq2),
                       ratio(s.dq2, s.pq2)});
      }
    return out;
  }

  double
  pooled_stress_error(const RveDatabase &reference,
                      const RveDatabase &other,
                      const bool         training)
  {
    const Paths a = group(reference), b = group(other);
    double      ds2 = 0.0, s2 = 0.0;
    bool        any = false;
    for (const auto &key : a.keys)
      {
        const auto it = b.rows.find(key);
        if (it == b.rows.end() || is_training_path(key.second) != training)
          continue;
        const Sums s = sums(reference, other, a.rows.at(key), it->second);
        ds2 += s.ds2;
        s2 += s.s2;
        any = true;
      }
    return any ? ratio(ds2, s2) : std::numeric_limits<double>::quiet_NaN();
  }
} // namespace compax::coupling
