#pragma once

#include "dem/nonlocal/nonlocal_bed_system.h"
#include "dem/solver/newton_krylov.h"
#include "dem/solver/trust_region_newton.h"

#include <array>
#include <iosfwd>
#include <limits>
#include <string>
#include <vector>

namespace compax::dem
{
  /// Which Newton method solves the jammed steps.
  enum class BedSolver
  {
    /// TrustRegionNewton with the approximate K of NonlocalBedSystem
    /// (local stiffness at gamma + gamma_NL) and its energy-like acceptance.
    trust_region,
    /// NewtonKrylov (exact Jacobian-vector products, GMRES,
    /// residual-norm backtracking), with the trust region as fallback.
    newton_krylov,
    /// TrustRegionNewton with nonlocal_equilibrium_options(): trust
    /// region on the frozen-angle Hessian
    /// (matrix-free, with the nonlocal amplification (I - D C)^-1), exact
    /// Newton-Krylov near equilibrium.
    nonlocal_trust_region
  };

  /// Settings of compact_square_die_bed().
  struct BedCompactionOptions
  {
    /// Final in-die relative density [-].
    double final_density = 0.80;
    /// Relative-density increment of the upper punch per step [-].
    double density_step = 0.005;
    /// Upper-punch pressure at which consolidation ends [Pa]: below it the
    /// bed rearranges (FIRE), above it each step is a Newton solve.
    double jamming_pressure = 1e5;
    /// FIRE: relative residual, iterations per step, and the force floor
    /// (fraction of p_jam pi R_mean^2 below which forces are negligible).
    double fire_tolerance       = 1e-3;
    int    fire_iterations      = 50000;
    double force_floor_fraction = 1e-2;
    /// Consolidate with Hertz contacts (gamma_NL = 0, no Algorithm 1)
    /// until the bed jams, then switch the nonlocal terms on: below the
    /// jamming pressure the overlaps, hence the nonlocal terms, are
    /// negligible, and FIRE needs thousands of residuals there.
    bool hertz_consolidation = true;
    /// Jammed steps start from the last converged increment (secant) when
    /// that leaves a smaller residual than the affine predictor.
    bool                secant_predictor = true;
    BedSolver           solver           = BedSolver::nonlocal_trust_region;
    EquilibriumOptions  newton;
    NewtonKrylovOptions krylov;
    EquilibriumOptions  nonlocal_newton = nonlocal_equilibrium_options();
  };

  /// One converged step.
  struct BedCompactionPoint
  {
    double relative_density = 0.0;
    /// Punch gap H [m].
    double height = 0.0;
    /// Force on each wall, indexed by SquareDie::Face [N].
    std::array<double, SquareDie::n_faces> wall_force{};
    /// Mean of the four die-wall forces [N].
    double lateral_force = 0.0;
    /// Whether the step was solved by Newton (the bed was jammed).
    bool jammed = false;
    /// Newton iterations (trust-region plus Newton-Krylov), FIRE
    /// iterations, rejected or backtracked steps, Algorithm 1 sweeps.
    int         newton_iterations = 0;
    int         fire_iterations   = 0;
    int         rejected_steps    = 0;
    std::size_t sweeps            = 0;
    /// max_i |F_i| / mean contact force at the end [-].
    double relative_residual = 0.0;
    /// Loaded contacts per particle [-].
    double coordination = 0.0;
    /// Largest gamma_NL / gamma of a loaded contact [-].
    double nonlocal_ratio = 0.0;
    bool   converged      = true;
  };

  /// Outcome of compact_square_die_bed().
  struct BedCompactionResult
  {
    std::vector<BedCompactionPoint> points;
    /// Whether the final density was reached.
    bool complete = false;
    /// First density that could not be solved (NaN if complete).
    double failure_density = std::numeric_limits<double>::quiet_NaN();
    /// Why the path ended early.
    std::string stop_reason;
    /// Final positions.
    ParticleSystem particles;
  };

  /**
   * Consolidation and compaction of a bed in a square die under
   * displacement control (Gonzalez & Cuitino 2012, Sec. 4.2, Fig. 19):
   * the upper punch moves in relative-density increments with an affine
   * predictor of the particle heights; while the bed carries less than the
   * jamming pressure it is relaxed by FIRE (particle rearrangement), then
   * every step is a static equilibrium solved by Newton. The die walls and
   * the lower punch stay fixed. A step that cannot be solved (for the
   * nonlocal formulation: beyond its limit point, where Algorithm 1
   * diverges) ends the path and is reported.
   */
  BedCompactionResult
  compact_square_die_bed(ParticleSystem                      particles,
                         const std::vector<ElasticMaterial> &materials,
                         SquareDie                           die,
                         bool                                nonlocal,
                         const BedCompactionOptions         &options,
                         std::ostream *progress = nullptr);
} // namespace compax::dem
