#pragma once

#include "dem/contact/contact_response.h"
#include "dem/contact/particle_law.h"
#include "dem/dynamics/dem_material.h"
#include "dem/periodic/periodic_cell.h"
#include "dem/periodic/periodic_pairs.h"
#include "dem/solver/contact_model.h"

#include <Eigen/Core>

#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

namespace compax::dem
{
  /// Time step and neighbour-list controls of ExplicitDem.
  struct DynamicsSettings
  {
    /// dt <= rayleigh_factor * dt_Rayleigh(R_min) [-].
    double rayleigh_factor = 0.2;
    /**
     * dt <= stiffness_factor * 2 / omega_max [-], omega_max^2 bounded by
     * 2 max_i K_i / m_i with K_i the summed normal and (3.5 x, for the
     * rotational coupling) tangential contact stiffnesses of particle i.
     * Needed because the un/reloading branch of the plastic law is up to
     * k2/k1 = 120 times stiffer than Hertz; the Rayleigh bound does not
     * see that.
     */
    double stiffness_factor = 0.3;
    /// Verlet skin [m]; 0 chooses a quarter of the smallest radius.
    double skin = 0.0;
    /// Factor on every mass and moment of inertia (density scaling for
    /// quasi-static runs; 1 = physical) [-].
    double mass_scaling = 1.0;
  };

  /// The particles as a structure of arrays (one array per quantity).
  struct DynamicParticles
  {
    /// Centres, unwrapped (pairs carry their periodic image) [m].
    std::vector<Eigen::Vector3d> position;
    std::vector<Eigen::Vector3d> velocity;         ///< [m/s]
    std::vector<Eigen::Vector3d> angular_velocity; ///< [1/s]
    std::vector<Eigen::Vector3d> force;            ///< last evaluation [N]
    std::vector<Eigen::Vector3d> torque;           ///< last evaluation [N m]
    std::vector<double>          radius;           ///< [m]
    std::vector<double>          mass;             ///< scaled [kg]
    std::vector<double>          inverse_mass;
    std::vector<double>          inverse_inertia;
    /// Particle stress sigma_i = sum_c f_c (x) b_c / V_i of the last force
    /// evaluation (f the contact force on i, b the branch vector from the
    /// centre to the contact point; tension positive) [Pa].
    std::vector<Eigen::Matrix3d> stress;
    /// tr(sigma_i)/3 of the last evaluation, fed to the normal law of the
    /// next one as P_ij = p_i + p_j (tension positive) [Pa].
    std::vector<double> pressure;
    /// Velocity imposed: forces are computed but do not accelerate it.
    std::vector<unsigned char> kinematic;

    std::size_t
    size() const
    {
      return position.size();
    }
  };

  /// A horizontal plate z = position with outward normal -z (bottom) or +z
  /// (top), moving along z.
  struct Plate
  {
    double position = 0.0; ///< [m]
    double velocity = 0.0; ///< dz/dt [m/s]
    /// Force the particles exert on the plate, last evaluation [N].
    Eigen::Vector3d force = Eigen::Vector3d::Zero();
  };

  /**
   * One particle-particle contact candidate of the Verlet list with its
   * history (the normal law's internal variables, e.g. delta_max of
   * Eq. 11; the tangential spring of Eq. 4) and the values of the last
   * force evaluation.
   */
  struct DynamicPairContact
  {
    std::uint32_t i;
    std::uint32_t j;
    LatticeImage  image;
    /// H n, the translation of j's image [m].
    Eigen::Vector3d offset;
    /// Internal variables of the normal law (delta_max [m] of the
    /// multi-contact law; those of the ContactModel's law).
    ContactHistory history;
    /// Accumulated tangential displacement xi [m] (F_t = -k_t xi - ...).
    Eigen::Vector3d tangential;
    /// Overlap of the last evaluation, <= 0 when apart [m].
    double overlap;
    /// Normal force of the normal law (without the dashpot) [N].
    double normal_force;
  };

  /// A particle's contact with one plate: history and last values.
  struct PlateContact
  {
    ContactHistory  history;
    Eigen::Vector3d tangential   = Eigen::Vector3d::Zero();
    double          overlap      = 0.0;
    double          normal_force = 0.0;
  };

  /**
   * Explicit discrete element method with the multi-contact law of
   * Giannis 2021: velocity Verlet for translation and rotation (Eq. 1);
   * normal force of MulticontactAdhesiveLaw (Eqs. 6-14) plus a Hertzian
   * dashpot set from the coefficient of restitution (Eq. 2,
   * restitution_damping.h); Mindlin tangential spring
   * k_t = 8 G* sqrt(R* delta) with its dashpot, the displacement
   * integrated from the tangential velocity (Eqs. 3-4) and rotated into the
   * current tangent plane, limited by Coulomb |F_t| <= mu max(F_n, 0);
   * constant directional rolling torque (Eq. 5) with R_r = R*, limited so
   * it cannot reverse the relative rotation within a step; two horizontal
   * plates; a cell periodic along any lattice directions (PeriodicCell).
   *
   * Multi-contact coupling: after each force evaluation every particle's
   * stress tensor sigma_i = sum_c f_c (x) b_c / V_i (V_i = 4/3 pi R_i^3)
   * and p_i = tr sigma_i / 3 are stored; the next evaluation passes
   * P_ij = p_i + p_j = (tr sigma_i + tr sigma_j)/3 to the law (p_i for a
   * plate, which carries no particle stress). The lag of one step keeps
   * the evaluation explicit and O(N).
   *
   * Neighbours: Verlet list from PeriodicCellGrid with a skin, rebuilt when
   * the largest displacement plus radius growth since the last build
   * reaches half the skin; histories are carried over by merging the two
   * sorted lists. The force loop allocates nothing.
   *
   * Plates have infinite radius and the wall elastic constants; the wall
   * is the contact partner "j" (a rigid body moving with the plate).
   *
   * Any particle law instead of the multi-contact one: use_contact_model()
   * takes the normal force of every contact from a ContactModel, the same
   * interface through which the static die and periodic-cell solvers
   * evaluate their laws (the bonded law of Gonzalez 2018 or a registered
   * law without context, e.g. Hertz or Walton-Braun). Each time step is a
   * state of the dynamics, so the law's updated_history() is applied
   * after every evaluation.
   */
  class ExplicitDem
  {
  public:
    ExplicitDem(const DemMaterial      &material,
                const PeriodicCell     &cell,
                const DynamicsSettings &settings = {});

    /// Adds a particle at rest; returns its index.
    std::size_t
    add_particle(const Eigen::Vector3d &position, double radius);

    /// Changes a radius (growth), with its mass and inertia.
    void
    set_radius(std::size_t i, double radius);

    /// Imposes the particle's velocities: forces act on it but do not
    /// change them.
    void
    set_kinematic(std::size_t i, bool kinematic);

    DynamicParticles &
    particles()
    {
      return p;
    }

    const DynamicParticles &
    particles() const
    {
      return p;
    }

    /// Adds the plates z = bottom (facing up) and z = top (facing down).
    void
    add_plates(double bottom, double top);

    bool
    has_plates() const
    {
      return plates_enabled;
    }

    Plate &
    bottom_plate()
    {
      return plates[0];
    }

    Plate &
    top_plate()
    {
      return plates[1];
    }

    const Plate &
    bottom_plate() const
    {
      return plates[0];
    }

    const Plate &
    top_plate() const
    {
      return plates[1];
    }

    /// Replaces the normal law parameters (e.g. elastic for growing, the
    /// calibrated law for compaction).
    void
    set_normal_law(const MulticontactAdhesiveLaw::Parameters &law);

    /**
     * Normal forces from @p model's laws between particles of its material
     * 0 (ContactModel::pair_law) and against rigid plates
     * (ContactModel::wall_law) instead of the multi-contact law; the
     * DemMaterial keeps the masses, the tangential springs, the dashpots
     * (on the law's stiffness dP/dgamma) and the Rayleigh step. A contact
     * keeps its internal variables while it stays in the Verlet list, so
     * a bonded pair pulled apart carries its bridge's tension (overlap
     * below 0) until the law breaks it. Forgets every contact history.
     */
    void
    use_contact_model(const ContactModel &model);

    /// Whether the normal forces come from a ContactModel.
    bool
    uses_contact_model() const
    {
      return model.has_value();
    }

    /// Switches sliding and rolling friction on or off.
    void
    set_friction(bool enabled)
    {
      friction = enabled;
    }

    /// Forgets every contact history (delta_max, tangential springs).
    void
    reset_contact_history();

    /// One velocity Verlet step of length time_step().
    void
    step();

    /// Fixes dt (0 restores the automatic choice).
    void
    set_fixed_time_step(double dt)
    {
      fixed_dt = dt;
    }

    const DemMaterial &
    material() const
    {
      return mat;
    }

    const PeriodicCell &
    cell() const
    {
      return periodic_cell;
    }

    double
    time() const
    {
      return t;
    }

    /// The step the next call of step() will take [s].
    double
    time_step();

    /// rayleigh_factor * dt_Rayleigh of the smallest particle [s].
    double
    rayleigh_limit() const;

    std::uint64_t
    steps() const
    {
      return step_count;
    }

    std::uint64_t
    neighbour_rebuilds() const
    {
      return rebuild_count;
    }

    /// Translational and rotational kinetic energy (scaled masses) [J].
    double
    kinetic_energy() const;

    /**
     * Energy stored in the contact springs [J]: per contact the work the
     * normal law returns when unloaded along its current un/reloading
     * branch from delta to the plastic overlap delta_0,
     * k2* [2/5 (delta^{5/2} - delta_0^{5/2}) - x_0 (delta - delta_0)]
     * (2/5 k1 delta^{5/2} for a Hertz contact), plus k_t |xi|^2 / 2 of the
     * tangential spring. The multi-contact term is not a potential and is
     * left out. Throws std::logic_error with a ContactModel, whose laws
     * declare no stored energy.
     */
    double
    elastic_energy() const;

    /// (1/V) sum_i V_i sigma_i, the Love-Weber average stress of the
    /// particles in a volume V [Pa] (tension positive).
    Eigen::Matrix3d
    average_stress(double volume) const;

    /// Particle-particle contacts with positive overlap.
    std::size_t
    contact_count() const;

    /// Particle-plate contacts with positive overlap.
    std::size_t
    wall_contact_count() const;

    const std::vector<DynamicPairContact> &
    pair_contacts() const
    {
      return pairs;
    }

    /// Contact of particle i with the bottom (0) or top (1) plate.
    const PlateContact &
    wall_contact(std::size_t i, int plate) const
    {
      return walls[2 * i + plate];
    }

    /// Sum of the particle volumes 4/3 pi R^3 [m^3].
    double
    solid_volume() const;

  private:
    /// Rebuilds the Verlet list if needed (or if forced).
    void
    update_neighbours(bool force);

    /// Contact forces, torques, particle stresses; increments the
    /// tangential springs by v_t dt.
    void
    compute_forces(double dt);

    DemMaterial               mat;
    PeriodicCell              periodic_cell;
    DynamicsSettings          settings;
    DynamicParticles          p;
    std::vector<PlateContact> walls;
    Plate                     plates[2];
    bool                      plates_enabled = false;
    bool                      friction       = true;

    // Pair constants.
    double E_pp, G_pp, E_pw, G_pw, zeta_pp, zeta_pw;

    /// The particle laws, if they replace the multi-contact law; then
    /// pair_laws[k] belongs to pairs[k] and wall_laws[i] to particle i.
    std::optional<ContactModel> model;
    std::vector<ParticleLaw>    pair_laws;
    std::vector<ParticleLaw>    next_pair_laws;
    std::vector<ParticleLaw>    wall_laws;
    /// A radius changed since the pair laws were built.
    bool laws_stale = false;

    // Verlet list.
    PeriodicCellGrid                grid;
    std::vector<ImagePair>          candidates;
    std::vector<DynamicPairContact> pairs;
    std::vector<DynamicPairContact> next_pairs;
    std::vector<Eigen::Vector3d>    position_at_build;
    std::vector<double>             radius_at_build;
    double                          skin_at_build = 0.0;
    bool                            list_valid    = false;

    // Per-step scratch.
    std::vector<double> stiffness_sum;

    bool          forces_valid  = false;
    double        dt            = 0.0;
    double        fixed_dt      = 0.0;
    double        t             = 0.0;
    std::uint64_t step_count    = 0;
    std::uint64_t rebuild_count = 0;
  };
} // namespace compax::dem
