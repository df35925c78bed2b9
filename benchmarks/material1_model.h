#pragma once

#include "dem/solver/contact_model.h"

namespace compax::benchmarks
{
  /// Material 1 of Gonzalez 2018 (Table 1) with its bonds, the material of
  /// the benchmarked beds and cells.
  inline const dem::ContactModel &
  material1_model()
  {
    static const dem::ContactModel m(
      dem::ElastoplasticMaterial{5e9, 0.25, 150e6, 2.0}, 1.26e6);
    return m;
  }
} // namespace compax::benchmarks
