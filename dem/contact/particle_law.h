#pragma once

#include "dem/contact/bonded_elastoplastic.h"
#include "dem/contact/registered_laws.h"

#include <optional>
#include <type_traits>
#include <variant>
#include <vector>

/**
 * @file
 * The law a contact of a particle solver (die bed, periodic cell) holds by
 * value: the bonded elasto-plastic law of Gonzalez 2018, or any registered
 * law that needs no context. A std::variant keeps the contact lists
 * contiguous and the calls direct (every law is a final class); the
 * functions below dispatch on it.
 */

namespace compax::dem
{
  namespace internal
  {
    /// Variant appends every law of the list whose needs_context is false.
    template <typename Variant, typename List>
    struct WithLocalLaws;

    template <typename... Chosen>
    struct WithLocalLaws<std::variant<Chosen...>, LawList<>>
    {
      using type = std::variant<Chosen...>;
    };

    template <typename... Chosen, typename Law, typename... Rest>
    struct WithLocalLaws<std::variant<Chosen...>, LawList<Law, Rest...>>
    {
      using type =
        typename WithLocalLaws<std::conditional_t<Law::needs_context,
                                                  std::variant<Chosen...>,
                                                  std::variant<Chosen..., Law>>,
                               LawList<Rest...>>::type;
    };
  } // namespace internal

  /// The bonded law, then every registered law without context.
  using ParticleLaw =
    typename internal::WithLocalLaws<std::variant<BondedElastoplasticLaw>,
                                     RegisteredLaws>::type;

  /// Force, exact stiffness and contact radius at overlap gamma [m].
  inline ContactResponse
  law_response(const ParticleLaw    &law,
               const double          gamma,
               const ContactHistory &history)
  {
    return std::visit(
      [&](const auto &l) { return l.evaluate(gamma, history, {}); }, law);
  }

  /// The internal variables after a converged state at overlap gamma.
  inline ContactHistory
  updated_history(const ParticleLaw    &law,
                  const double          gamma,
                  const ContactHistory &history)
  {
    return std::visit(
      [&](const auto &l) { return l.updated_history(gamma, history, {}); },
      law);
  }

  /// ContactLaw::unloading_stiffness() of the law [N/m].
  inline double
  unloading_stiffness(const ParticleLaw    &law,
                      const double          gamma,
                      const ContactHistory &history)
  {
    return std::visit(
      [&](const auto &l) { return l.unloading_stiffness(gamma, history, {}); },
      law);
  }

  /// ContactLaw::loads_plastically() of the law.
  inline bool
  loads_plastically(const ParticleLaw    &law,
                    const double          gamma,
                    const ContactHistory &history)
  {
    return std::visit(
      [&](const auto &l) { return l.loads_plastically(gamma, history, {}); },
      law);
  }

  /// ContactLaw::separation_reach() of the law [m].
  inline double
  separation_reach(const ParticleLaw &law, const ContactHistory &history)
  {
    return std::visit(
      [&](const auto &l) { return l.separation_reach(history, {}); }, law);
  }

  /// ContactLaw::bonded(): whether the contact holds a solid bridge.
  inline bool
  bonded(const ParticleLaw &law, const ContactHistory &history)
  {
    return std::visit([&](const auto &l) { return l.bonded(history); }, law);
  }

  /// ContactLaw::history_variables(): the law's declared internal variables.
  inline std::vector<HistoryVariable>
  history_variables(const ParticleLaw &law)
  {
    return std::visit([](const auto &l) { return l.history_variables(); }, law);
  }

  /**
   * The plastic contact radius a_p [m] of a bonded contact, 0 for other
   * laws: the radius of the area a contact keeps after plastic loading,
   * which the bed statistics average and the unjammed-step limits read.
   */
  inline double
  plastic_radius(const ParticleLaw &law, const ContactHistory &history)
  {
    return std::holds_alternative<BondedElastoplasticLaw>(law)
             ? BondedElastoplasticLaw::a_p(history)
             : 0.0;
  }

  /**
   * A contact's share of the bonding surface of Gonzalez 2018 Sec. 5.6,
   * a_p^2 [m^2]: the area plastic loading created, while the contact
   * touches (contact radius a > 0 in @p response, the law's response at the
   * current overlap). A pair that has parted keeps a_p as its history but
   * bonds no more.
   */
  inline double
  bonding_area_squared(const ParticleLaw     &law,
                       const ContactHistory  &history,
                       const ContactResponse &response)
  {
    const double a_p = plastic_radius(law, history);
    return response.contact_radius > 0.0 ? a_p * a_p : 0.0;
  }

  /// The bonded law of a contact that holds it (std::bad_variant_access
  /// otherwise), for what only that law defines (a_p, breakage overlap).
  inline const BondedElastoplasticLaw &
  bonded_law(const ParticleLaw &law)
  {
    return std::get<BondedElastoplasticLaw>(law);
  }

  /// A copy of @p law if a particle solver can hold it, else nothing.
  template <std::size_t alternative = 0>
  std::optional<ParticleLaw>
  as_particle_law(const ContactLaw &law)
  {
    if constexpr (alternative == std::variant_size_v<ParticleLaw>)
      return std::nullopt;
    else
      {
        using Law = std::variant_alternative_t<alternative, ParticleLaw>;
        if (const auto *l = dynamic_cast<const Law *>(&law))
          return ParticleLaw(std::in_place_index<alternative>, *l);
        return as_particle_law<alternative + 1>(law);
      }
  }
} // namespace compax::dem
