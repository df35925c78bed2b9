#include "io/content_hash.h"

#include <fstream>
#include <vector>

namespace compax::io
{
  std::uint64_t
  hash64(const void *data, const std::size_t size, std::uint64_t hash)
  {
    const auto *p = static_cast<const unsigned char *>(data);
    for (std::size_t i = 0; i < size; ++i)
      {
        hash ^= p[i];
        hash *= 0x100000001b3ull;
      }
    return hash;
  }

  std::string
  to_hex(const std::uint64_t value)
  {
    static const char digits[] = "0123456789abcdef";
    std::string       s(16, '0');
    for (int k = 0; k < 16; ++k)
      s[15 - k] = digits[(value >> (4 * k)) & 0xf];
    return s;
  }

  std::string
  file_hash(const std::string &path)
  {
    std::ifstream in(path, std::ios::binary);
    if (!in)
      return {};
    std::uint64_t     h = hash64(nullptr, 0);
    std::vector<char> buffer(1 << 16);
    while (in)
      {
        in.read(buffer.data(), buffer.size());
        h = hash64(buffer.data(), static_cast<std::size_t>(in.gcount()), h);
      }
    if (in.bad())
      return {};
    return to_hex(h);
  }
} // namespace compax::io
