#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

/**
 * @file
 * Content hashes that say whether two files or two byte strings are the
 * same: the archives' checksums, the fingerprints of a run's parameters and
 * of the files they name (a DPC table, a mesh).
 */

namespace compax::io
{
  /// FNV-1a 64-bit hash of @p size bytes, continuing from @p hash.
  std::uint64_t
  hash64(const void   *data,
         std::size_t   size,
         std::uint64_t hash = 0xcbf29ce484222325ull);

  /// 16 lower-case hexadecimal digits.
  std::string
  to_hex(std::uint64_t value);

  /// hash64 of a file's bytes in hex; empty if it cannot be read.
  std::string
  file_hash(const std::string &path);
} // namespace compax::io
