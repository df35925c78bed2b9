#include "apps/die/kill_switch.h"

#include <signal.h>
#include <unistd.h>

#include <cstdlib>

namespace compax::cli
{
  KillSwitch::KillSwitch(std::streambuf *file)
      : file(file)
  {
    if (const char *row = std::getenv("COMPAX_TEST_KILL_AFTER_ROW"))
      prefix = std::string(row) + ",";
  }

  KillSwitch::~KillSwitch()
  {
    file->sputn(line.data(), static_cast<std::streamsize>(line.size()));
  }

  int
  KillSwitch::overflow(const int c)
  {
    if (c == traits_type::eof())
      return 0;
    const char ch = static_cast<char>(c);
    xsputn(&ch, 1);
    return c;
  }

  std::streamsize
  KillSwitch::xsputn(const char *s, const std::streamsize n)
  {
    for (std::streamsize i = 0; i < n; ++i)
      {
        line += s[i];
        if (s[i] != '\n')
          continue;
        file->sputn(line.data(), static_cast<std::streamsize>(line.size()));
        if (!prefix.empty() && line.rfind(prefix, 0) == 0)
          {
            file->pubsync();
            ::kill(::getpid(), SIGKILL);
          }
        line.clear();
      }
    return n;
  }

  int
  KillSwitch::sync()
  {
    return file->pubsync();
  }
} // namespace compax::cli
