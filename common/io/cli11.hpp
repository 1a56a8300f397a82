#pragma once
// CLI11, the flag parser. It is header-only: every file that includes it compiles and optimises
// its functions again (about half the code of a chapter program's main.cpp). A run parses its
// flags once, so g++ compiles them without optimisation: about 3 s less per file.

#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC push_options
#pragma GCC optimize("O0")
#include <CLI/CLI.hpp>
#pragma GCC pop_options
#else
#include <CLI/CLI.hpp>
#endif
