#pragma once
// SHA-256 (FIPS 180-4) of a byte string, as 64 lowercase hex digits. For provenance headers.

#include <string>

namespace rbdgen
{

std::string sha256Hex(const std::string & data);

} // namespace rbdgen
