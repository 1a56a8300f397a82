#pragma once
// Its own header, so the files that only refuse work need not include CLI11.

#include <stdexcept>

namespace mcrt {

/// A request that parses but cannot be done (too much work, inconsistent flags): exit code 2.
class UsageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace mcrt
