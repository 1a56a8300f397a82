#pragma once
// The code under test, as the assignment tests see it: subject() answers every request a
// check makes. Built normally, it is a LocalSubject (the student's functions in this process:
// the ordinary suite, a kit's self-grading). Built as a checker (MCRT_REMOTE_SUBJECT, which
// scripts/grade uses), it is a RemoteSubject: the requests go to the subject program and
// no student code is linked into the test program.

#include "assignments/subject/requests.hpp"

#ifdef MCRT_REMOTE_SUBJECT
#include "assignments/subject/remote_subject.hpp"
#else
#include "assignments/subject/local_subject.hpp"
#endif

namespace mcrt::testing::assignment {

#ifdef MCRT_REMOTE_SUBJECT
using Subject = RemoteSubject;
#else
using Subject = LocalSubject;
#endif

/// The one subject of this test program.
inline Subject& subject() {
  static Subject s;
  return s;
}

/// A bulk producer that maps `f` over a vector: a known-wrong variant (diagnosis_test.cpp) or
/// a student's function called in-process, where a check takes a Subject's bulk request.
template <class F>
auto each(F f) {
  return [f](const auto& inputs) {
    std::vector<std::decay_t<decltype(f(inputs.front()))>> out;
    out.reserve(inputs.size());
    for (const auto& x : inputs) out.push_back(f(x));
    return out;
  };
}

}  // namespace mcrt::testing::assignment
