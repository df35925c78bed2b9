#include "fem/tablet_solver.h"

#include "fem/axisymmetric_kinematics.h"
#include "fem/wall_contact.h"

#include <deal.II/base/mpi.h>
#include <deal.II/base/numbers.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/fe_values_extractors.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/reference_cell.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/trilinos_solver.h>
#include <deal.II/lac/vector.h>
#include <deal.II/numerics/data_component_interpretation.h>
#include <deal.II/numerics/data_out.h>
#include <deal.II/numerics/vector_tools.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <limits>
#include <stdexcept>
#include <utility>

namespace compax::fem
{
  namespace
  {
    constexpr double pi = dealii::numbers::PI;

    /// Whole-tablet factor of the model: the r-z measure already integrates
    /// over the circumference; the 3-D model is a quarter.
    template <int dim>
    constexpr double
    symmetry_factor()
    {
      return dim == 2 ? 1.0 : 4.0;
    }

    template <int dim>
    double
    measure_weight(const dealii::Point<dim> &p)
    {
      if constexpr (dim == 2)
        return axisymmetric_measure(p);
      else
        return 1.0;
    }

    /// Small-strain tensor (3-D, hoop included in r-z) of a displacement
    /// with value @p v and gradient @p g at @p p.
    template <int dim>
    dealii::SymmetricTensor<2, 3>
    strain(const dealii::Tensor<2, dim> &g,
           const dealii::Tensor<1, dim> &v,
           const dealii::Point<dim>     &p)
    {
      if constexpr (dim == 2)
        return axisymmetric_strain(g, v, p[0]);
      else
        {
          (void)v;
          (void)p;
          return dealii::symmetrize(g);
        }
    }

    /// Deformation gradient I + grad du in 3-D (hoop stretch in r-z).
    template <int dim>
    dealii::Tensor<2, 3>
    deformation(const dealii::Tensor<2, dim> &g,
                const dealii::Tensor<1, dim> &v,
                const dealii::Point<dim>     &p)
    {
      dealii::Tensor<2, 3> F;
      for (unsigned int i = 0; i < dim; ++i)
        for (unsigned int j = 0; j < dim; ++j)
          F[i][j] = g[i][j];
      if constexpr (dim == 2)
        F[2][2] = v[0] / p[0];
      for (unsigned int i = 0; i < 3; ++i)
        F[i][i] += 1.0;
      return F;
    }

  } // namespace

  double
  wall_friction_coefficient(const TabletSolverSettings &s, const double rho)
  {
    const auto &t = s.wall_friction_table;
    if (t.empty())
      return s.wall_friction;
    if (rho <= t.front().first)
      return t.front().second;
    for (std::size_t i = 1; i < t.size(); ++i)
      if (rho < t[i].first)
        {
          const double w
            = (rho - t[i - 1].first) / (t[i].first - t[i - 1].first);
          return (1.0 - w) * t[i - 1].second + w * t[i].second;
        }
    return t.back().second;
  }

  template <int dim>
  TabletSolver<dim>::TabletSolver(
    const TabletSolverSettings          &settings_in,
    std::shared_ptr<const MaterialModel> material_in,
    MPI_Comm                             communicator)
      : settings(settings_in)
      , material(std::move(material_in))
      , comm(communicator)
      , tria(communicator)
      , fe(dealii::FE_Q<dim>(settings_in.degree), dim)
      , cell_quadrature(settings_in.degree + 1)
      , face_quadrature(settings_in.degree + 1)
  {
    settings.geometry.validate();
    make_compact(tria, settings.geometry, settings.refinements);
    if (settings.die_top <= 0.0)
      settings.die_top = settings.geometry.fill_height;
    space            = std::make_unique<FeSpace<dim>>(tria, fe);
    const auto &dofs = space->dof_handler();

    constraints.reinit(space->locally_relevant_dofs());
    const dealii::Functions::ZeroFunction<dim> zero(dim);
    // Displacement component @p c vanishes on @p boundary (the axis of
    // symmetry, or a symmetry plane of the 3-D quarter).
    const auto fix_component
      = [&](const dealii::types::boundary_id boundary, const unsigned int c) {
          dealii::VectorTools::interpolate_boundary_values(
            dofs,
            boundary,
            zero,
            constraints,
            fe.component_mask(dealii::FEValuesExtractors::Scalar(c)));
        };
    if constexpr (dim == 2)
      fix_component(axis, 0);
    else
      {
        fix_component(symmetry_x, 0);
        fix_component(symmetry_y, 1);
      }
    constraints.close();

    space->reinit_matrix(matrix, constraints);
    space->reinit_vector(rhs);
    space->reinit_vector(du);
    space->reinit_vector(u);
    space->reinit_vector(last_du);
    axial_dofs
      = dealii::DoFTools::extract_dofs(
          dofs, fe.component_mask(dealii::FEValuesExtractors::Scalar(dim - 1)))
        & space->locally_owned_dofs();
    space->reinit_ghosted_vector(du_ghost);
    space->reinit_ghosted_vector(u_ghost);
    mapping = std::make_unique<
      dealii::MappingQEulerian<dim, dealii::TrilinosWrappers::MPI::Vector>>(
      settings.degree, dofs, u_ghost);

    const std::size_t n_cells = tria.n_active_cells();
    material_history.reinit(n_cells * cell_quadrature.size(),
                            material->n_history());
    for (std::size_t k = 0; k < material_history.n_points(); ++k)
      material->initialize(settings.initial_relative_density,
                           material_history.committed(k));
    material_history.revert();
    friction_history.reinit(n_cells * dealii::GeometryInfo<dim>::faces_per_cell
                              * face_quadrature.size(),
                            dim);

    double h = std::numeric_limits<double>::max();
    for (const auto &cell : tria.active_cell_iterators())
      if (cell->is_locally_owned())
        for (unsigned int d = 0; d < dim; ++d)
          h = std::min(h, cell->extent_in_direction(d));
    h_min          = dealii::Utilities::MPI::min(h, comm);
    initial_volume = volume();
    upper_position = settings.geometry.fill_height;
    lower_position = 0.0;
  }

  template <int dim>
  double
  TabletSolver<dim>::punch_area() const
  {
    const double R = settings.geometry.radius();
    return pi * R * R;
  }

  template <int dim>
  dealii::types::global_dof_index
  TabletSolver<dim>::n_dofs() const
  {
    return space->dof_handler().n_dofs();
  }

  template <int dim>
  dealii::types::global_cell_index
  TabletSolver<dim>::n_cells() const
  {
    return tria.n_global_active_cells();
  }

  template <int dim>
  double
  TabletSolver<dim>::penalty() const
  {
    double E = 0.0;
    for (const auto &cell : tria.active_cell_iterators())
      if (cell->is_locally_owned())
        for (unsigned int q = 0; q < cell_quadrature.size(); ++q)
          E = std::max(E,
                       material->youngs_modulus(material_history.committed(
                         cell->active_cell_index() * cell_quadrature.size()
                         + q)));
    E = dealii::Utilities::MPI::max(E, comm);
    return settings.penalty_factor * E / h_min;
  }

  template <int dim>
  double
  TabletSolver<dim>::volume() const
  {
    dealii::FEValues<dim> fv(*mapping,
                             fe,
                             cell_quadrature,
                             dealii::update_quadrature_points
                               | dealii::update_JxW_values);
    double                V = 0.0;
    for (const auto &cell : space->dof_handler().active_cell_iterators())
      if (cell->is_locally_owned())
        {
          fv.reinit(cell);
          for (const unsigned int q : fv.quadrature_point_indices())
            V += fv.JxW(q) * measure_weight(fv.quadrature_point(q));
        }
    return symmetry_factor<dim>() * dealii::Utilities::MPI::sum(V, comm);
  }

  template <int dim>
  double
  TabletSolver<dim>::mean_relative_density() const
  {
    return settings.initial_relative_density * initial_volume / volume();
  }

  template <int dim>
  dealii::SymmetricTensor<2, 3>
  TabletSolver<dim>::mean_stress() const
  {
    return volume_average([this](dealii::ArrayView<const double> h) {
      return material->stress(h);
    });
  }

  template <int dim>
  dealii::SymmetricTensor<2, 3>
  TabletSolver<dim>::volume_average(
    const std::function<dealii::SymmetricTensor<2, 3>(
      dealii::ArrayView<const double>)> &field) const
  {
    dealii::FEValues<dim>         fv(*mapping,
                             fe,
                             cell_quadrature,
                             dealii::update_quadrature_points
                               | dealii::update_JxW_values);
    dealii::SymmetricTensor<2, 3> sum;
    double                        V = 0.0;
    for (const auto &cell : space->dof_handler().active_cell_iterators())
      if (cell->is_locally_owned())
        {
          fv.reinit(cell);
          for (const unsigned int q : fv.quadrature_point_indices())
            {
              const double dV
                = fv.JxW(q) * measure_weight(fv.quadrature_point(q));
              sum += dV
                     * field(material_history.committed(
                       cell->active_cell_index() * cell_quadrature.size() + q));
              V += dV;
            }
        }
    for (unsigned int i = 0; i < 3; ++i)
      for (unsigned int j = i; j < 3; ++j)
        sum[i][j] = dealii::Utilities::MPI::sum(sum[i][j], comm);
    return sum / dealii::Utilities::MPI::sum(V, comm);
  }

  template <int dim>
  std::vector<dealii::Point<dim>>
  TabletSolver<dim>::boundary_positions(
    const dealii::types::boundary_id id) const
  {
    std::vector<dealii::Point<dim>> mine;
    for (const auto &cell : space->dof_handler().active_cell_iterators())
      if (cell->is_locally_owned())
        for (const unsigned int f : cell->face_indices())
          if (cell->face(f)->at_boundary()
              && cell->face(f)->boundary_id() == id)
            for (const unsigned int v : cell->face(f)->vertex_indices())
              {
                dealii::Point<dim> x = cell->face(f)->vertex(v);
                for (unsigned int d = 0; d < dim; ++d)
                  x[d] += u_ghost[cell->face(f)->vertex_dof_index(v, d)];
                mine.push_back(x);
              }
    std::vector<dealii::Point<dim>> all;
    for (const auto &part : dealii::Utilities::MPI::all_gather(comm, mine))
      all.insert(all.end(), part.begin(), part.end());
    return all;
  }

  template <int dim>
  bool
  TabletSolver<dim>::assemble(const bool with_matrix)
  {
    if (with_matrix)
      matrix = 0.0;
    rhs      = 0.0;
    du_ghost = du;

    const dealii::FEValuesExtractors::Vector     disp(0);
    dealii::FEValues<dim>                        fv(*mapping,
                             fe,
                             cell_quadrature,
                             dealii::update_values | dealii::update_gradients
                               | dealii::update_quadrature_points
                               | dealii::update_JxW_values);
    dealii::FEFaceValues<dim>                    ffv(*mapping,
                                  fe,
                                  face_quadrature,
                                  dealii::update_values
                                    | dealii::update_quadrature_points
                                    | dealii::update_JxW_values);
    const unsigned int                           n  = fe.n_dofs_per_cell();
    const unsigned int                           nq = cell_quadrature.size();
    const unsigned int                           nf = face_quadrature.size();
    dealii::FullMatrix<double>                   cell_matrix(n, n);
    dealii::Vector<double>                       cell_rhs(n);
    std::vector<dealii::types::global_dof_index> dof_indices(n);
    std::vector<dealii::SymmetricTensor<2, 3>>   B(n), CB(n);
    std::vector<dealii::Tensor<2, dim>>          grads(nq);
    std::vector<dealii::Tensor<1, dim>> vals(nq), face_du(nf), face_u(nf);
    std::vector<unsigned int>           component(n);
    for (unsigned int i = 0; i < n; ++i)
      component[i] = fe.system_to_component_index(i).first;

    const double eps_t = settings.tangential_penalty_ratio * eps_n;
    const double eps_w = 1e-6 * eps_n;
    bool         ok    = true;
    TabletForces f;
    unsigned int wall_points = 0, sliding_points = 0;
    double       f_int_squared = 0.0;

    for (const auto &cell : space->dof_handler().active_cell_iterators())
      {
        if (!cell->is_locally_owned())
          continue;
        fv.reinit(cell);
        cell_matrix = 0.0;
        cell_rhs    = 0.0;
        fv[disp].get_function_gradients(du_ghost, grads);
        fv[disp].get_function_values(du_ghost, vals);
        for (unsigned int q = 0; q < nq; ++q)
          {
            const dealii::Point<dim> &x  = fv.quadrature_point(q);
            const double              dV = fv.JxW(q) * measure_weight(x);
            MaterialIncrement         inc;
            inc.strain_increment      = strain<dim>(grads[q], vals[q], x);
            inc.deformation_increment = deformation<dim>(grads[q], vals[q], x);
            const std::size_t k       = cell->active_cell_index() * nq + q;
            MaterialResponse  r;
            if (!material->evaluate(inc,
                                    material_history.committed(k),
                                    material_history.trial(k),
                                    r))
              ok = false;
            material->rotate(material_history.trial(k),
                             incremental_rotation(inc.deformation_increment));
            for (unsigned int i = 0; i < n; ++i)
              {
                B[i]            = strain<dim>(fv[disp].gradient(i, q),
                                   fv[disp].value(i, q),
                                   x);
                const double fi = (B[i] * r.stress) * dV;
                cell_rhs(i) -= fi;
                f_int_squared += fi * fi;
                if (with_matrix)
                  CB[i] = r.tangent * B[i];
              }
            if (with_matrix)
              for (unsigned int i = 0; i < n; ++i)
                for (unsigned int j = 0; j < n; ++j)
                  cell_matrix(i, j) += (B[i] * CB[j]) * dV;
          }

        // Friction of the wall next to this cell, from its density at the
        // start of the increment.
        double mu_cell = settings.wall_friction;
        if (!settings.wall_friction_table.empty())
          {
            double rho = 0.0;
            for (unsigned int q = 0; q < nq; ++q)
              rho += material->relative_density(material_history.committed(
                       cell->active_cell_index() * nq + q))
                     / nq;
            mu_cell = wall_friction_coefficient(settings, rho);
          }
        for (const unsigned int face : cell->face_indices())
          {
            if (!cell->face(face)->at_boundary())
              continue;
            const auto id = cell->face(face)->boundary_id();
            if (id != die_wall && id != upper_punch && id != lower_punch)
              continue;
            ffv.reinit(cell, face);
            ffv[disp].get_function_values(du_ghost, face_du);
            ffv[disp].get_function_values(u_ghost, face_u);
            for (unsigned int q = 0; q < nf; ++q)
              {
                const std::size_t k
                  = (cell->active_cell_index()
                       * dealii::GeometryInfo<dim>::faces_per_cell
                     + face)
                      * nf
                    + q;
                dealii::ArrayView<double> fric = friction_history.trial(k);
                const dealii::Point<dim> &x    = ffv.quadrature_point(q);
                const double              dA   = ffv.JxW(q) * measure_weight(x);
                dealii::Tensor<1, dim>    normal;
                double                    gap0 = 0.0, mu = 0.0, curvature = 0.0;
                if (id == upper_punch)
                  {
                    if (!target_upper_present)
                      {
                        std::fill(fric.begin(), fric.end(), 0.0);
                        continue;
                      }
                    const PunchProfile &punch = settings.geometry.upper_punch;
                    if (punch.is_flat())
                      {
                        normal[dim - 1] = 1.0;
                        gap0            = target_upper - x[dim - 1];
                      }
                    else
                      {
                        // Gap and normal where the point is now: exact on
                        // the curved face (with the curvature term below).
                        const PunchGap<dim> g
                          = punch.gap<dim>(x + face_du[q], target_upper);
                        normal    = g.normal;
                        gap0      = g.gap + face_du[q] * normal;
                        curvature = g.curvature;
                      }
                  }
                else if (id == lower_punch)
                  {
                    normal[dim - 1] = -1.0;
                    gap0            = x[dim - 1] - target_lower;
                  }
                else
                  {
                    // Above the die top (where the point is now, so a
                    // tablet pushed out is free at the end of the step)
                    // there is no wall.
                    if (x[dim - 1] + face_du[q][dim - 1] >= settings.die_top)
                      {
                        std::fill(fric.begin(), fric.end(), 0.0);
                        continue;
                      }
                    const dealii::Point<dim> X = x - face_u[q];
                    if constexpr (dim == 2)
                      normal[0] = 1.0;
                    else
                      {
                        const double rX = std::hypot(X[0], X[1]);
                        normal[0]       = X[0] / rX;
                        normal[1]       = X[1] / rX;
                      }
                    gap0 = -(face_u[q] * normal);
                    const double taper_start
                      = settings.die_top - settings.die_top_taper_length;
                    if (settings.die_top_taper_length > 0.0
                        && x[dim - 1] > taper_start)
                      gap0 += settings.die_top_taper_opening
                              * (x[dim - 1] - taper_start)
                              / settings.die_top_taper_length;
                    mu = mu_cell;
                  }
                dealii::Tensor<1, dim>                old_friction;
                const dealii::ArrayView<const double> committed
                  = std::as_const(friction_history).committed(k);
                for (unsigned int d = 0; d < dim; ++d)
                  old_friction[d] = committed[d];
                WallContactResponse<dim> c = wall_contact<dim>(
                  normal, gap0, face_du[q], old_friction, eps_n, eps_t, mu);
                for (unsigned int d = 0; d < dim; ++d)
                  fric[d] = c.friction[d];
                if (id == lower_punch)
                  {
                    const double g = gap0 - face_du[q] * normal;
                    c.traction += eps_w * g * normal;
                    c.tangent -= eps_w * dealii::outer_product(normal, normal);
                  }
                if (curvature > 0.0 && c.pressure > 0.0)
                  {
                    // The normal of a curved face turns with the point:
                    // d(-p n)/du += -p (I - n n) / rho.
                    dealii::Tensor<2, dim> P
                      = dealii::unit_symmetric_tensor<dim>();
                    P -= dealii::outer_product(normal, normal);
                    c.tangent -= (c.pressure * curvature) * P;
                  }
                if (id == upper_punch)
                  f.upper_punch_force += c.pressure * normal[dim - 1] * dA;
                else if (id == lower_punch)
                  f.lower_punch_force -= (c.traction * normal) * dA;
                else
                  {
                    f.die_wall_normal_force += c.pressure * dA;
                    f.die_wall_friction_force += c.friction[dim - 1] * dA;
                    if (c.pressure > 0.0)
                      {
                        f.die_wall_contact_area += dA;
                        ++wall_points;
                        if (!c.stick)
                          ++sliding_points;
                      }
                  }
                for (unsigned int i = 0; i < n; ++i)
                  {
                    const double phi_i = ffv.shape_value(i, q);
                    if (phi_i == 0.0)
                      continue;
                    cell_rhs(i) += phi_i * c.traction[component[i]] * dA;
                    if (with_matrix)
                      for (unsigned int j = 0; j < n; ++j)
                        cell_matrix(i, j)
                          -= phi_i * ffv.shape_value(j, q)
                             * c.tangent[component[i]][component[j]] * dA;
                  }
              }
          }

        cell->get_dof_indices(dof_indices);
        if (with_matrix)
          constraints.distribute_local_to_global(
            cell_matrix, cell_rhs, dof_indices, matrix, rhs);
        else
          constraints.distribute_local_to_global(cell_rhs, dof_indices, rhs);
      }
    if (with_matrix)
      matrix.compress(dealii::VectorOperation::add);
    rhs.compress(dealii::VectorOperation::add);

    const double s = symmetry_factor<dim>();
    trial_forces.upper_punch_force
      = s * dealii::Utilities::MPI::sum(f.upper_punch_force, comm);
    trial_forces.lower_punch_force
      = s * dealii::Utilities::MPI::sum(f.lower_punch_force, comm);
    trial_forces.die_wall_normal_force
      = s * dealii::Utilities::MPI::sum(f.die_wall_normal_force, comm);
    trial_forces.die_wall_contact_area
      = s * dealii::Utilities::MPI::sum(f.die_wall_contact_area, comm);
    trial_forces.die_wall_friction_force
      = s * dealii::Utilities::MPI::sum(f.die_wall_friction_force, comm);
    const double n_wall
      = dealii::Utilities::MPI::sum(double(wall_points), comm);
    trial_forces.sliding_fraction
      = n_wall > 0
          ? dealii::Utilities::MPI::sum(double(sliding_points), comm) / n_wall
          : 0.0;
    internal_force_norm
      = std::sqrt(dealii::Utilities::MPI::sum(f_int_squared, comm));
    return dealii::Utilities::MPI::min(ok ? 1 : 0, comm) == 1;
  }

  template <int dim>
  bool
  TabletSolver<dim>::solve_increment(const double upper,
                                     const double lower,
                                     const bool   upper_present)
  {
    target_upper         = upper;
    target_lower         = lower;
    target_upper_present = upper_present;
    eps_n                = penalty();
    // Predictor: the last increment, scaled to this punch motion when the
    // punches keep moving the same way; at the start of ejection, a rigid
    // lift with the lower punch.
    const double d_upper = upper_present ? upper - upper_position : 0.0;
    const double d_lower = lower - lower_position;
    const double last_m2
      = last_d_upper * last_d_upper + last_d_lower * last_d_lower;
    const double along = d_upper * last_d_upper + d_lower * last_d_lower;
    du                 = 0.0;
    if (upper_present == last_upper_present && last_m2 > 0.0 && along > 0.0)
      du.add(along / last_m2, last_du);
    else if (!upper_present && d_lower > 0.0)
      for (const auto i : axial_dofs)
        du[i] = d_lower;
    du.compress(dealii::VectorOperation::insert);
    constraints.distribute(du);
    // Force scale below which a residual counts as zero: a strain of 1e-9
    // of the stiffest material over a punch face.
    const double floor
      = 1e-9 * eps_n * h_min / settings.penalty_factor * punch_area();
    // The material's stresses are resolved no finer than its resolution.
    const double tolerance
      = std::max(settings.tolerance, material->stress_resolution());
    dealii::SolverControl                  control(1, 0.0);
    dealii::TrilinosWrappers::SolverDirect direct(
      control,
      dealii::TrilinosWrappers::SolverDirect::AdditionalData(
        false, settings.direct_solver));
    dealii::TrilinosWrappers::MPI::Vector delta(du);
    // Newton with a lazy backtracking line search: the residual at the new
    // iterate comes with its tangent (one assembly per iteration); only if
    // it did not decrease enough is the step halved and re-assembled.
    // Contact and stick/slip switch discontinuously and a full step can
    // cycle between two active sets; a shorter step breaks the cycle.
    dealii::TrilinosWrappers::MPI::Vector du_start(du);
    double                                res_start = 0.0, alpha = 1.0;
    unsigned int                          halvings = 0, newton = 0;
    for (unsigned int it = 0; it <= 6 * (settings.max_iterations + 1); ++it)
      {
        const bool   ok  = assemble(true);
        const double res = ok ? rhs.l2_norm() : 0.0;
        if (it > 0 && halvings < 5
            && (!ok || !std::isfinite(res)
                || res >= (1.0 - 1e-4 * alpha) * res_start))
          {
            alpha *= 0.5;
            ++halvings;
            du = du_start;
            du.add(alpha, delta);
            continue;
          }
        if (!ok || !std::isfinite(res))
          return false;
        const double scale = std::max({internal_force_norm,
                                       trial_forces.upper_punch_force
                                         + trial_forces.lower_punch_force
                                         + trial_forces.die_wall_normal_force,
                                       floor});
        if (settings.verbose
            && dealii::Utilities::MPI::this_mpi_process(comm) == 0)
          std::cerr << "  newton " << iterations << " residual " << res
                    << " scale " << scale << " step " << alpha << '\n';
        if (res <= tolerance * scale)
          return true;
        if (newton >= settings.max_iterations)
          break;
        try
          {
            direct.solve(matrix, delta, rhs);
          }
        catch (...)
          {
            return false;
          }
        constraints.distribute(delta);
        du_start  = du;
        res_start = res;
        alpha     = 1.0;
        halvings  = 0;
        du.add(1.0, delta);
        ++newton;
        ++iterations;
      }
    return false;
  }

  template <int dim>
  void
  TabletSolver<dim>::commit()
  {
    material_history.commit();
    friction_history.commit();
    last_d_upper = target_upper_present ? target_upper - upper_position : 0.0;
    last_d_lower = target_lower - lower_position;
    last_upper_present = target_upper_present;
    last_du            = du;
    u += du;
    u_ghost          = u;
    du               = 0.0;
    upper_position   = target_upper;
    lower_position   = target_lower;
    upper_active     = target_upper_present;
    converged_forces = trial_forces;
  }

  template <int dim>
  bool
  TabletSolver<dim>::advance(const double upper,
                             const double lower,
                             const bool   upper_present)
  {
    iterations = 0;
    // Pending sub-targets as fractions of the increment, processed in order.
    const double up0 = upper_position, low0 = lower_position;
    double       done = 0.0, size = 1.0;
    unsigned int cuts = 0;
    while (done < 1.0 - 1e-12)
      {
        const double t = std::min(1.0, done + size);
        const double up
          = upper_present && upper_active ? up0 + t * (upper - up0) : upper;
        if (solve_increment(up, low0 + t * (lower - low0), upper_present))
          {
            commit();
            done = t;
            // Grow back after a success.
            if (cuts > 0 && size < 1.0)
              size = std::min(1.0 - done, 2.0 * size);
          }
        else
          {
            if (++cuts > settings.max_step_cuts)
              {
                du = 0.0;
                return false;
              }
            size *= 0.5;
          }
      }
    return true;
  }

  namespace
  {
    constexpr std::uint64_t checkpoint_magic = 0x636f6d7061785431; // compaxT1

    template <typename T>
    void
    put(std::ostream &out, const T &value)
    {
      out.write(reinterpret_cast<const char *>(&value), sizeof(T));
    }

    template <typename T>
    T
    get(std::istream &in)
    {
      T value{};
      in.read(reinterpret_cast<char *>(&value), sizeof(T));
      return value;
    }

    void
    put_vector(std::ostream                                &out,
               const dealii::TrilinosWrappers::MPI::Vector &v)
    {
      put(out, static_cast<std::uint64_t>(v.locally_owned_size()));
      for (const auto i : v.locally_owned_elements())
        put(out, double(v[i]));
    }

    bool
    get_vector(std::istream &in, dealii::TrilinosWrappers::MPI::Vector &v)
    {
      if (get<std::uint64_t>(in) != v.locally_owned_size())
        return false;
      for (const auto i : v.locally_owned_elements())
        v[i] = get<double>(in);
      v.compress(dealii::VectorOperation::insert);
      return static_cast<bool>(in);
    }
  } // namespace

  template <int dim>
  void
  TabletSolver<dim>::save_state(const std::filesystem::path &folder) const
  {
    const unsigned int rank = dealii::Utilities::MPI::this_mpi_process(comm);
    const auto    file = folder / ("solver." + std::to_string(rank) + ".bin");
    std::ofstream out(file, std::ios::binary);
    put(out, checkpoint_magic);
    put(out, static_cast<std::uint32_t>(dim));
    put(out, dealii::Utilities::MPI::n_mpi_processes(comm));
    put(out, static_cast<std::uint64_t>(n_dofs()));
    put(out, upper_position);
    put(out, lower_position);
    put(out, upper_active);
    put(out, last_d_upper);
    put(out, last_d_lower);
    put(out, last_upper_present);
    put(out, initial_volume);
    put(out, converged_forces);
    put_vector(out, u);
    put_vector(out, last_du);
    material_history.save(out);
    friction_history.save(out);
    out.close();
    if (!out)
      throw std::runtime_error("cannot write checkpoint " + file.string());
    // State the material keeps outside the histories (e.g. FE2 RVEs).
    material->save_state(folder, rank);
  }

  template <int dim>
  void
  TabletSolver<dim>::load_state(const std::filesystem::path &folder)
  {
    const unsigned int rank = dealii::Utilities::MPI::this_mpi_process(comm);
    const auto    file = folder / ("solver." + std::to_string(rank) + ".bin");
    std::ifstream in(file, std::ios::binary);
    const std::string what = "checkpoint " + file.string() + ": ";
    if (!in)
      throw std::runtime_error(what + "cannot be read");
    if (get<std::uint64_t>(in) != checkpoint_magic
        || get<std::uint32_t>(in) != dim)
      throw std::runtime_error(what + "not a checkpoint of this model");
    if (get<unsigned int>(in) != dealii::Utilities::MPI::n_mpi_processes(comm))
      throw std::runtime_error(what
                               + "written with another number of MPI ranks");
    if (get<std::uint64_t>(in) != n_dofs())
      throw std::runtime_error(what + "written for another mesh");
    upper_position     = get<double>(in);
    lower_position     = get<double>(in);
    upper_active       = get<bool>(in);
    last_d_upper       = get<double>(in);
    last_d_lower       = get<double>(in);
    last_upper_present = get<bool>(in);
    initial_volume     = get<double>(in);
    converged_forces   = get<TabletForces>(in);
    if (!get_vector(in, u) || !get_vector(in, last_du)
        || !material_history.load(in) || !friction_history.load(in))
      throw std::runtime_error(
        what + "does not match this mesh, material or partition");
    material->load_state(folder, rank);
    u_ghost = u;
    du      = 0.0;
  }

  template <int dim>
  std::string
  TabletSolver<dim>::write_fields(const std::filesystem::path &folder,
                                  const unsigned int           index) const
  {
    return write_fields(folder, index, 0.0, true, false).vtu_record;
  }

  template <int dim>
  void
  write_xdmf_record(const std::vector<dealii::XDMFEntry> &entries,
                    const std::filesystem::path          &file,
                    MPI_Comm                              communicator)
  {
    if (dealii::Utilities::MPI::this_mpi_process(communicator) != 0)
      return;
    std::ofstream out(file);
    out << "<?xml version=\"1.0\" ?>\n"
        << "<!DOCTYPE Xdmf SYSTEM \"Xdmf.dtd\" []>\n"
        << "<Xdmf Version=\"2.0\">\n"
        << "  <Domain>\n"
        << "    <Grid Name=\"CellTime\" GridType=\"Collection\" "
           "CollectionType=\"Temporal\">\n";
    for (const auto &entry : entries)
      out << entry.get_xdmf_content(
        3, dealii::ReferenceCells::get_hypercube<dim>());
    out << "    </Grid>\n"
        << "  </Domain>\n"
        << "</Xdmf>\n";
    if (!out)
      throw std::runtime_error("cannot write " + file.string());
  }

  template void
  write_xdmf_record<2>(const std::vector<dealii::XDMFEntry> &,
                       const std::filesystem::path &,
                       MPI_Comm);
  template void
  write_xdmf_record<3>(const std::vector<dealii::XDMFEntry> &,
                       const std::filesystem::path &,
                       MPI_Comm);

  template <int dim>
  FieldFiles
  TabletSolver<dim>::write_fields(const std::filesystem::path &folder,
                                  const unsigned int           index,
                                  const double                 time,
                                  const bool                   vtu,
                                  const bool                   hdf5) const
  {
    const std::size_t     n_cells = tria.n_active_cells();
    dealii::Vector<float> rho(n_cells), p(n_cells), q(n_cells), eps_v(n_cells),
      eps_eq(n_cells), rank(n_cells);
    std::vector<dealii::Vector<float>> sigma(4, dealii::Vector<float>(n_cells));
    const unsigned int                 nq = cell_quadrature.size();
    const unsigned int comps[4][2]        = {{0, 0}, {1, 1}, {2, 2}, {0, 1}};
    for (const auto &cell : tria.active_cell_iterators())
      {
        if (!cell->is_locally_owned())
          continue;
        const std::size_t c = cell->active_cell_index();
        for (unsigned int k = 0; k < nq; ++k)
          {
            const auto h   = material_history.committed(c * nq + k);
            const auto s   = material->stress(h);
            const auto e_p = material->plastic_strain(h);
            rho[c] += material->relative_density(h) / nq;
            p[c] += pressure(s) / nq;
            q[c] += von_mises(s) / nq;
            eps_v[c] += -dealii::trace(e_p) / nq;
            eps_eq[c]
              += std::sqrt(2.0 / 3.0) * dealii::deviator(e_p).norm() / nq;
            for (unsigned int m = 0; m < 4; ++m)
              sigma[m][c] += s[comps[m][0]][comps[m][1]] / nq;
          }
        rank[c] = dealii::Utilities::MPI::this_mpi_process(comm);
      }
    dealii::DataOut<dim> out;
    out.attach_dof_handler(space->dof_handler());
    const std::vector<std::string> names(dim, "displacement");
    out.add_data_vector(
      u_ghost,
      names,
      dealii::DataOut<dim>::type_dof_data,
      std::vector<
        dealii::DataComponentInterpretation::DataComponentInterpretation>(
        dim, dealii::DataComponentInterpretation::component_is_part_of_vector));
    out.add_data_vector(rho,
                        "relative_density",
                        dealii::DataOut<dim>::type_cell_data);
    out.add_data_vector(p, "pressure", dealii::DataOut<dim>::type_cell_data);
    out.add_data_vector(q,
                        "von_mises_stress",
                        dealii::DataOut<dim>::type_cell_data);
    const char *stress_names[2][4]
      = {{"stress_rr", "stress_zz", "stress_tt", "stress_rz"},
         {"stress_xx", "stress_yy", "stress_zz", "stress_xy"}};
    for (unsigned int m = 0; m < 4; ++m)
      out.add_data_vector(sigma[m],
                          stress_names[dim - 2][m],
                          dealii::DataOut<dim>::type_cell_data);
    out.add_data_vector(eps_v,
                        "volumetric_plastic_strain",
                        dealii::DataOut<dim>::type_cell_data);
    out.add_data_vector(eps_eq,
                        "equivalent_plastic_strain",
                        dealii::DataOut<dim>::type_cell_data);
    out.add_data_vector(rank, "mpi_rank", dealii::DataOut<dim>::type_cell_data);
    out.build_patches(*mapping, settings.degree);
    FieldFiles files;
    if (vtu)
      files.vtu_record = out.write_vtu_with_pvtu_record(
        folder.string() + "/", "tablet", index, comm, 4, 1);
    if (hdf5)
      {
        files.hdf5_file
          = "tablet_" + dealii::Utilities::int_to_string(index, 4) + ".h5";
        // No merging of the nodes that cells share: a merged node would
        // carry the value of one of its cells only.
        dealii::DataOutBase::DataOutFilter filter(
          dealii::DataOutBase::DataOutFilterFlags(false, true));
        out.write_filtered_data(filter);
        out.write_hdf5_parallel(filter,
                                (folder / files.hdf5_file).string(),
                                comm);
        files.xdmf = out.create_xdmf_entry(filter, files.hdf5_file, time, comm);
      }
    return files;
  }

  template class TabletSolver<2>;
  template class TabletSolver<3>;
} // namespace compax::fem
