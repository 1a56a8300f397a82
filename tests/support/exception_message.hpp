#pragma once
// The message of the exception a call throws, for tests that check what an error says.

#include <string>

namespace mcrt::testing {

/// The what() of the exception of type E that `action` throws, or "" if it throws none.
template <class E, class Action>
std::string message_of(Action action) {
  try {
    action();
  } catch (const E& e) {
    return e.what();
  }
  return "";
}

}  // namespace mcrt::testing
