#pragma once
// nlohmann-json, for summary.json, timings.json and the tables' JSON. It is header-only: every
// file that includes it compiles and optimises its functions again. A run writes a few small
// JSON files, so g++ compiles them without optimisation, which saves compile time only.

#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC push_options
#pragma GCC optimize("O0")
#include <nlohmann/json.hpp>
#pragma GCC pop_options
#else
#include <nlohmann/json.hpp>
#endif
