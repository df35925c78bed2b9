#pragma once

#include "dem/rve/homogenization.h"
#include "dem/rve/periodic_bed.h"
#include "dem/rve/periodic_packing.h"
#include "dem/rve/rve_loading.h"
#include "fem/material_model.h"

#include <cstdint>
#include <vector>

namespace compax::coupling
{
  /// What an RVE-backed material point is made of.
  struct RveMaterialSpec
  {
    /// Packing statistics of every point's cell; its relative density is
    /// replaced by the one the tablet model initializes the point with.
    dem::PeriodicPackingSpec packing;
    dem::RveLoadingOptions   loading;
    /// Distinct packings drawn (seeds packing.seed + k); point n starts
    /// from a copy of packing (n / points_per_cell) mod pool_size, so
    /// start-up costs pool_size packings, not one per point.
    unsigned int pool_size = 4;
    /// Consecutive points that start from the same pool packing [-]: the
    /// quadrature points of one cell (the solver numbers points cell by
    /// cell), so that a cell's points jam in the same step, not one by one
    /// at their packings' different jamming densities (which strains the
    /// still loose ones hard). 1: point n takes packing n mod pool_size.
    unsigned int points_per_cell = 1;
    /// Index of the compaction axis in the tablet model's stress frame
    /// (r-z model: 1, the axial row of (r, z, theta); 3-D: 2) [-]: the
    /// axis along which the pool packings are consolidated.
    unsigned int compaction_axis = 2;
    /// Logarithmic axial strain per step of the uniaxial consolidation
    /// that brings each pool packing to its jamming pressure [-].
    double consolidation_strain_step = 0.005;
    /// Jammed cells to use instead of drawing packings (e.g. regular
    /// lattices): taken as they are, each one's relative density is the
    /// density at which a point switches to it. Empty: draw and
    /// consolidate `pool_size` packings.
    std::vector<dem::PeriodicBed> pool;
    /// Young's modulus of a weak isotropic hypoelastic skeleton in
    /// parallel with the RVE [Pa] (Poisson's ratio 0.25): a loose cell has
    /// no contact network and a zero tangent, which leaves the continuum
    /// Newton singular; the floor keeps it well-posed. What it adds to the
    /// stress is set by floor_stress.
    double tangent_floor_modulus = 1e6;
    /// What the floor contributes to the stress of a point.
    enum class FloorStress
    {
      /// Default. While the point is loose the floor's stress is integrated
      /// hypoelastically and is the point's stress (with the jamming ramp);
      /// at the jamming switch it is released: the jammed packing was
      /// consolidated through the same loose densification and its stress
      /// (the jamming pressure) already is the powder's, so keeping the
      /// floor's would count that stage twice, and it would stay in the
      /// ejected tablet (it barely recovers on unloading: Ef x the summed
      /// strain increments, -0.4 MPa mean and -0.7 MPa axial after
      /// uniaxial compaction from 0.5 to 0.9 at 1 MPa, which the RVEs of
      /// the free tablet balance in tension: of the order of its tensile
      /// strength). Once jammed the floor is only a regularisation
      /// of the tangent (stress from the RVE alone, tangent RVE + floor):
      /// the continuum Newton is then a modified Newton whose error is
      /// multiplied by at most Ef / (Ef + E_rve) per iteration (~1e-3 for a
      /// dense RVE, more just after jamming, where the RVEs are soft:
      /// tablet_fe2_250.prm takes 9 % more Newton iterations, mostly in the
      /// compaction steps after jamming), and stays well-posed if an RVE loses
      /// its contacts.
      released_at_jamming,
      /// The former scheme: the floor's stress is integrated over the whole
      /// cycle and added to the RVE's (consistent tangent, but the floor's
      /// compaction stress, ~Ef x the accumulated volumetric strain, stays
      /// in the ejected tablet).
      accumulated
    };
    FloorStress floor_stress = FloorStress::released_at_jamming;
    /// Relative accuracy of the homogenized stress the continuum Newton
    /// balances to [-] (MaterialModel::stress_resolution): an RVE's stress
    /// is piecewise smooth, contacts opening, closing or switching between
    /// loading and unloading change it by ~1e-4 of its magnitude between
    /// neighbouring trial strains, and a tighter tolerance only makes the
    /// continuum Newton wander at that level.
    double stress_resolution = 1e-3;
    /// The canonical text of the parameters the RVE states depend on,
    /// stored with them in a checkpoint (archive kind "fe2-rve-states") and
    /// checked when they are loaded; empty: none.
    std::string checkpoint_parameters;
  };

  /// Work of the RVEs of one MPI rank so far (the RVE share of an FE2 run).
  struct RveMaterialCounters
  {
    /// Trial RVE solves (equilibrium, stress and condensed tangent) [-].
    std::size_t solves = 0;
    /// ... of which fell back from the affine predictor to continuation [-].
    std::size_t continuations = 0;
    /// ... of which found no equilibrium (the continuum step is cut) [-].
    std::size_t failures = 0;
    /// Wall time in them [s].
    double seconds = 0.0;
    /// Wall time of drawing and consolidating the pool at start-up [s].
    double pool_seconds = 0.0;
  };

  /**
   * FE2 material point of the tablet model (fem::MaterialModel): each
   * quadrature point owns a periodic RVE; the symmetric strain increment
   * of the continuum step strains its cell (H -> (I + deps) H), the
   * fluctuations are equilibrated with frozen internal variables, and the
   * point returns the Love-Weber stress and the condensed tangent of that
   * trial state, plus those of a weak elastic floor (see the spec: by
   * default the floor carries stress only while the point is loose, and
   * only its tangent once the point is jammed).
   *
   * Consolidation, as in the die (Gonzalez 2018 §5): a powder below its
   * jamming point has no contact network and carries no stress to speak
   * of, and an RVE there is a gas that Newton cannot equilibrate (FIRE
   * can, at great cost, and the cell shears freely). So a point starts
   * unjammed and carries only the floor while its density (mass balance)
   * stays below the jamming density of its pool packing (the floor's
   * stress is released when the point switches, see
   * RveMaterialSpec::FloorStress); each pool
   * packing is brought to its jamming pressure once, at start-up, by
   * uniaxial compaction. In the step that crosses it, the point takes a
   * copy of the jammed packing and strains it by the part of the
   * increment beyond the jamming density; from then on it is a full FE2
   * point. Equilibrium from the affine predictor falls back to
   * continuation (sub-steps of the increment, histories frozen) so the
   * trial stays a function of the committed cell and the increment only.
   * Every point reports its
   * packing's jammed modulus from the start, which sets the die-wall
   * penalty (set by the floor, the die gives way when points jam).
   *
   * Commit without a solver hook: the history holds the point's RVE index
   * and a step counter that each evaluation increments in the trial
   * history. When an evaluation finds the committed counter one ahead of
   * the RVE's, the solver has committed the last trial: that trial cell,
   * with the history update of Eq. (13) applied, becomes the committed
   * cell. A cut step leaves the counter, and the trial is recomputed from
   * the committed cell. rotate() (called at commit) rotates the trial cell
   * rigidly with the stress (objectivity of the updated-Lagrangian scheme).
   *
   * Not thread-safe (assembly is serial per MPI rank); the RVEs live with
   * their rank's quadrature points. Tablet checkpoints hold them
   * (save_state(), load_state()).
   */
  class RveMaterial : public fem::MaterialModel
  {
  public:
    RveMaterial(RveMaterialSpec spec, dem::ContactModel model);

    std::string
    name() const override
    {
      return "multiscale-fe2";
    }

    unsigned int
    n_history() const override
    {
      return 17;
    }

    void
    initialize(double                    relative_density,
               dealii::ArrayView<double> history) const override;

    bool
    evaluate(const fem::MaterialIncrement   &increment,
             dealii::ArrayView<const double> old_history,
             dealii::ArrayView<double>       new_history,
             fem::MaterialResponse          &response) const override;

    dealii::SymmetricTensor<2, 3>
    stress(dealii::ArrayView<const double> history) const override;

    double
    relative_density(dealii::ArrayView<const double> history) const override;

    dealii::SymmetricTensor<2, 3>
    plastic_strain(dealii::ArrayView<const double> history) const override;

    double
    youngs_modulus(dealii::ArrayView<const double> history) const override;

    double
    stress_resolution() const override
    {
      return spec.stress_resolution;
    }

    void
    rotate(dealii::ArrayView<double>   history,
           const dealii::Tensor<2, 3> &R) const override;

    /// Writes the rank's RVEs (committed and trial cell and committed
    /// counter of every point) and the pool to folder/rve.<rank>.h5,
    /// atomically (rve_material_checkpoint.cc).
    void
    save_state(const std::filesystem::path &folder,
               unsigned int                 rank) const override;

    /// Restores what save_state() wrote into a material whose points were
    /// initialized as in the saved run; throws std::runtime_error if the
    /// file is missing or malformed, holds another number of points or
    /// another pool.
    void
    load_state(const std::filesystem::path &folder,
               unsigned int                 rank) const override;

    /// Relative density at which pool packing k jams [-].
    double
    jamming_density(std::size_t k) const
    {
      return template_jamming_density[k];
    }

    /// Whether a point's committed state is a jammed RVE.
    static bool
    is_jammed(dealii::ArrayView<const double> history);

    /// The floor's share of a point's stress [Pa] (tension positive; the
    /// RVE's share is stress() minus it): zero once the point is jammed
    /// unless RveMaterialSpec::floor_stress is accumulated.
    static dealii::SymmetricTensor<2, 3>
    floor_stress(dealii::ArrayView<const double> history);

    /// Number of material points (RVEs) created so far.
    std::size_t
    n_points() const
    {
      return committed.size();
    }

    /// RVE work of this rank so far.
    const RveMaterialCounters &
    counters_so_far() const
    {
      return counters;
    }

    /// The committed cell of a point (tests, output).
    const dem::PeriodicBed &
    committed_cell(std::size_t point) const
    {
      return committed[point];
    }

  private:
    /**
     * A loose point whose trial passes its packing's jamming density
     * within the step: the part of the increment beyond it strains the
     * jammed packing linearly (its condensed tangent), added to @p
     * response with its exact derivative. Without it a loose cell in
     * series with a jammed one (stacked cells, or a cell next to one that
     * just switched) would carry the jammed cell's stress on the floor
     * alone, collapsing by far more than its jamming strain within the
     * Newton iterations; the switch to the RVE itself stays at the start of
     * the next step.
     */
    void
    add_jamming_ramp(const fem::MaterialIncrement &increment,
                     double                        rho_old,
                     std::size_t                   pooled,
                     fem::MaterialResponse        &response) const;

    /// Index of the pool packing `point` starts from.
    std::size_t
    pool_member(std::size_t point) const;

    /// Promotes the last trial of `point` if the solver committed it.
    void
    catch_up(std::size_t point, double committed_step) const;

    /// The pool: spec.pool as given, or drawn at density rho and
    /// consolidated; with the jamming densities and moduli.
    void
    make_templates(double rho) const;

    /// Draws pool_size packings at density rho and compacts each
    /// uniaxially to its jamming pressure.
    void
    consolidate_templates(double rho) const;

    /// Newton equilibrium of `cell` mapped affinely to F (false also
    /// when the cell cannot take F).
    bool
    solve_at(dem::PeriodicBed &cell, const Eigen::Matrix3d &F) const;

    /// Equilibrium of `start` deformed to F, into `cell`, with frozen
    /// histories: from the affine predictor, else by continuation in
    /// halved sub-steps, so the result depends on start and F only.
    bool
    equilibrate_at(dem::PeriodicBed       &cell,
                   const dem::PeriodicBed &start,
                   const Eigen::Matrix3d  &F) const;

    RveMaterialSpec   spec;
    dem::ContactModel model;
    // Mutable: evaluate() is const in the interface, the cells are the
    // material's own state, indexed by the point's history.
    mutable std::vector<dem::PeriodicBed> templates;
    mutable std::vector<double>           template_jamming_density;
    /// Axial entry of each packing's condensed tangent [Pa].
    mutable std::vector<double> template_modulus;
    /// Each packing's condensed tangent [Pa].
    mutable std::vector<dealii::SymmetricTensor<4, 3>> template_tangent;
    mutable double                                     template_density = -1.0;
    mutable std::vector<dem::PeriodicBed>              committed;
    mutable std::vector<dem::PeriodicBed>              trial;
    mutable std::vector<double>                        committed_steps;
    mutable dem::PeriodicAssembler                     assembler;
    mutable dem::TrustRegionNewton                     newton;
    mutable dem::FireRelaxation                        fire;
    mutable dem::TangentCalculator                     tangent;
    mutable RveMaterialCounters                        counters;
  };

  /// The 4th-order tensor of a Voigt matrix with engineering shears
  /// (C_ijkl = dsigma_ij / deps_kl with minor symmetries).
  dealii::SymmetricTensor<4, 3>
  from_voigt(const dem::Matrix6d &C);
} // namespace compax::coupling
