#pragma once
/// SHA-256 (FIPS 180-4), for the reference cache: its description records the hash of the PFM
/// it describes, so a reader can tell that the two were written together.

#include <string>
#include <string_view>

namespace mcrt {

/// The SHA-256 digest of `bytes` as 64 lowercase hexadecimal digits.
std::string sha256_hex(std::string_view bytes);

}  // namespace mcrt
