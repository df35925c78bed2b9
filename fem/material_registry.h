#pragma once

#include "fem/material_model.h"

#include <deal.II/base/parameter_handler.h>

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace compax::fem
{
  /**
   * A continuum material as the tablet model offers it by name. It declares
   * and reads its own entries of the subsection Material (the pattern of
   * ASPECT's models), so that the command line's Selection, its --help and
   * the generated parameter reference all come from the registry and a new
   * material is one registration, not edits of the tablet command.
   */
  struct RegisteredMaterial
  {
    /// The value of Material/Model that selects it, e.g. "linear-elastic".
    std::string name;
    /// One sentence for the documentation of Material/Model.
    std::string description;
    /// Declares the material's own entries; called inside the subsection
    /// Material. Empty: it has none there.
    std::function<void(dealii::ParameterHandler &)> declare;
    /**
     * Reads the material's entries (inside the subsection Material) and
     * builds it; throws input::InputError naming a bad entry. Empty for a
     * material its caller builds at run time from other subsections (the
     * particle-derived ones, which need the RVE, MPI and an output folder).
     */
    std::function<std::shared_ptr<const MaterialModel>(
      dealii::ParameterHandler &)>
      create;
  };

  /// Materials by name, in the order they were added (the order their
  /// entries are declared in).
  class MaterialRegistry
  {
  public:
    /// Adds @p material; throws std::logic_error if its name is taken.
    void
    add(RegisteredMaterial material);

    /// The material named @p name; throws std::out_of_range if none is.
    const RegisteredMaterial &
    find(const std::string &name) const;

    const std::vector<RegisteredMaterial> &
    materials() const
    {
      return list;
    }

    /// The names as a Patterns::Selection string, "a|b|c".
    std::string
    selection() const;

    /// "a: description; b: description" for Material/Model's help.
    std::string
    documentation() const;

    /// Declares every material's own entries in the current subsection.
    void
    declare_parameters(dealii::ParameterHandler &prm) const;

  private:
    std::vector<RegisteredMaterial> list;
  };

  /// The closed-form materials of the tablet model: drucker-prager-cap and
  /// linear-elastic.
  MaterialRegistry
  closed_form_materials();
} // namespace compax::fem
