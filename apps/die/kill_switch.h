#pragma once

#include <streambuf>
#include <string>

namespace compax::cli
{
  /**
   * die.csv as it is written, line by line. A test hook (fault injection)
   * for the kill-and-resume tests: with the environment variable
   * COMPAX_TEST_KILL_AFTER_ROW=<stage>,<branch>,<step> the process kills
   * itself (SIGKILL, no clean-up at all) right after that row reached the
   * file, as a kill from outside at that point would.
   */
  class KillSwitch : public std::streambuf
  {
  public:
    explicit KillSwitch(std::streambuf *file);

    ~KillSwitch() override;

  protected:
    int
    overflow(int c) override;

    std::streamsize
    xsputn(const char *s, std::streamsize n) override;

    int
    sync() override;

  private:
    std::streambuf *file;
    std::string     prefix;
    std::string     line;
  };
} // namespace compax::cli
