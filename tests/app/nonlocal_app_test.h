#pragma once

// The application tests of the nonlocal contact formulation (Gonzalez &
// Cuitino 2012) share their runs: a command with the elastic law and the
// nonlocal formulation beside the Hertz run of the same packing, and the
// refusal of the nonlocal formulation with the bonded elasto-plastic law.

#include "app_test_support.h"

#include <cmath>
#include <functional>
#include <string>

namespace compax::testing
{
  /// A command's parameter file for a contact law and formulation.
  using ContactParameters
    = std::function<std::string(const std::string &law,
                                const std::string &formulation)>;

  /// AppTest with the runs every nonlocal command test makes.
  class NonlocalAppTest : public AppTest
  {
  protected:
    /// Runs `compax <command>` with the elastic law, nonlocal into the
    /// folder `nl` and then Hertz into `hz` (the same packing): both
    /// succeed (fatal failure otherwise), the first reports the nonlocal
    /// formulation, and the nonlocal terms change the last @p column of
    /// @p stage in the output file @p csv by more than 1e-3 of the Hertz
    /// run's positive value.
    void
    expect_nonlocal_changes_hertz(const std::string       &command,
                                  const ContactParameters &parameters,
                                  const std::string       &csv,
                                  const std::string       &stage,
                                  const std::string       &column) const
    {
      write("nonlocal.prm", parameters("elastic", "nonlocal"));
      const auto r = compax(command + " nonlocal.prm -o nl");
      ASSERT_EQ(r.exit_code, 0) << r.err << r.out;
      EXPECT_NE(r.out.find("nonlocal contact formulation"), std::string::npos);

      write("hertz.prm", parameters("elastic", "hertz"));
      const auto h = compax(command + " hertz.prm -o hz");
      ASSERT_EQ(h.exit_code, 0) << h.err << h.out;

      const double nonlocal
        = last_in_stage(Csv(folder / "nl" / csv), stage, column);
      const double hertz
        = last_in_stage(Csv(folder / "hz" / csv), stage, column);
      ASSERT_GT(hertz, 0.0);
      EXPECT_GT(std::abs(nonlocal - hertz), 1e-3 * hertz);
    }

    /// The bonded elasto-plastic law with the nonlocal formulation is
    /// refused (exit code 2) naming the formulation's entry and the law it
    /// needs; returns the run for further checks of its message.
    RunResult
    expect_bonded_nonlocal_refused(const std::string       &command,
                                   const ContactParameters &parameters) const
    {
      write("bad.prm", parameters("bonded-elastoplastic", "nonlocal"));
      const auto r = compax(command + " bad.prm -o bad");
      EXPECT_EQ(r.exit_code, 2);
      EXPECT_NE(r.err.find("Contact/Formulation"), std::string::npos) << r.err;
      EXPECT_NE(r.err.find("Contact law = elastic"), std::string::npos)
        << r.err;
      return r;
    }
  };
} // namespace compax::testing
