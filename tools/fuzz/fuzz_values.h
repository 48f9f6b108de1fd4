// What the message fuzzers share: numbers drawn from the fuzzer's bytes the way bad messages
// carry them (NaN, infinities, any double or float, mostly a plausible range), and the check
// that aborts with the property that failed (libFuzzer then keeps the input).
#pragma once

#include <fuzzer/FuzzedDataProvider.h>

#include <cstdio>
#include <cstdlib>
#include <limits>

namespace spott_fuzz {

/// NaN, +-infinity, any value of T, or (half the time) a value in [lo, hi].
template <typename T>
T AnyNumber(FuzzedDataProvider& in, T lo, T hi) {
  switch (in.ConsumeIntegralInRange<int>(0, 5)) {
    case 0:
      return std::numeric_limits<T>::quiet_NaN();
    case 1:
      return in.ConsumeBool() ? std::numeric_limits<T>::infinity()
                              : -std::numeric_limits<T>::infinity();
    case 2:
      return in.ConsumeFloatingPoint<T>();
    default:
      return in.ConsumeFloatingPointInRange<T>(lo, hi);
  }
}

/// Aborts naming the fuzzer and the property when `ok` is false.
inline void Check(bool ok, const char* fuzzer, const char* what) {
  if (!ok) {
    std::fprintf(stderr, "%s: %s\n", fuzzer, what);
    std::abort();
  }
}

}  // namespace spott_fuzz
