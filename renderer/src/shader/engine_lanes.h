// The interpreter's building blocks: a slot's 64 lanes walked in steps of a lane type's width, the mask
// operations of structured control flow, and the handlers that look at single lanes (integer division,
// packing, derivatives). Private to engine_run.h.
#pragma once

#include <bit>
#include <cstdint>
#include <cstring>

#include "shader/engine.h"
#include "shader/lane_math.h"

#define RASTER_LANES_INLINE __attribute__((always_inline))

namespace raster::shader::run {

template <class T>
inline constexpr int kWidth = static_cast<int>(sizeof(T) / 4);

template <class T>
[[gnu::always_inline]] inline T load(const std::uint32_t* p) {
  T v;
  std::memcpy(&v, p, sizeof v);
  return v;
}
template <class T>
[[gnu::always_inline]] inline void put(std::uint32_t* p, const T& v) {
  std::memcpy(p, &v, sizeof v);
}

// d = fn(a), fn(a, b), fn(a, b, c), lane by lane, in the lane type T (reading the slots' bits as T).
// kUniform says which operands hold one value in all 64 lanes (bit 0: b, bit 1: c; ir.h's Instr::uniform):
// those are read once, not once a step.
template <class T, class Fn>
[[gnu::always_inline]] inline void lanes1(std::uint32_t* d, const std::uint32_t* a, Fn fn) {
  for (int i = 0; i < kBlockLanes; i += kWidth<T>) put(d + i, fn(load<T>(a + i)));
}
template <class T, int kUniform = 0, class Fn>
[[gnu::always_inline]] inline void lanes2(std::uint32_t* d, const std::uint32_t* a, const std::uint32_t* b,
                                          Fn fn) {
  if constexpr (kUniform & 1) {
    const T y = load<T>(b);
    for (int i = 0; i < kBlockLanes; i += kWidth<T>) put(d + i, fn(load<T>(a + i), y));
  } else {
    for (int i = 0; i < kBlockLanes; i += kWidth<T>) put(d + i, fn(load<T>(a + i), load<T>(b + i)));
  }
}
template <class T, int kUniform = 0, class Fn>
[[gnu::always_inline]] inline void lanes3(std::uint32_t* d, const std::uint32_t* a, const std::uint32_t* b,
                                          const std::uint32_t* c, Fn fn) {
  const T y0 = load<T>(b), z0 = load<T>(c);
  for (int i = 0; i < kBlockLanes; i += kWidth<T>)
    put(d + i, fn(load<T>(a + i), kUniform & 1 ? y0 : load<T>(b + i), kUniform & 2 ? z0 : load<T>(c + i)));
}
// A conversion: reads lanes as S, writes them as T (same width).
template <class S, class T, class Fn>
[[gnu::always_inline]] inline void convert1(std::uint32_t* d, const std::uint32_t* a, Fn fn) {
  for (int i = 0; i < kBlockLanes; i += kWidth<S>) put<T>(d + i, fn(load<S>(a + i)));
}

/// Any lane of the mask slot set; all set.
template <class U>
[[gnu::always_inline]] inline bool any_lane(const std::uint32_t* m) {
  U acc = load<U>(m);
  for (int i = kWidth<U>; i < kBlockLanes; i += kWidth<U>) acc |= load<U>(m + i);
  if constexpr (kWidth<U> == 1) {
    return acc != 0;
  } else {
    return detail::lane_bits(std::bit_cast<detail::IntLanes>(acc)) != 0;
  }
}
template <class U>
[[gnu::always_inline]] inline bool all_lanes(const std::uint32_t* m) {
  U acc = load<U>(m);
  for (int i = kWidth<U>; i < kBlockLanes; i += kWidth<U>) acc &= load<U>(m + i);
  if constexpr (kWidth<U> == 1) {
    return acc == ~0u;
  } else {
    return detail::lane_bits(std::bit_cast<detail::IntLanes>(acc)) == 0xffu;
  }
}

/// d = exec ? a : d: an assignment under control flow (a plain copy while every lane is live).
template <class U>
[[gnu::always_inline]] inline void store(std::uint32_t* d, const std::uint32_t* a, const std::uint32_t* r,
                                         bool full) {
  if (full) {
    std::memcpy(d, a, kBlockLanes * 4);
    return;
  }
  const std::uint32_t* exec = r + static_cast<std::size_t>(kExecSlot) * kBlockLanes;
  for (int i = 0; i < kBlockLanes; i += kWidth<U>)
    put(d + i, select(load<U>(exec + i), load<U>(a + i), load<U>(d + i)));
}

/// d = exec & cond ? a : d: an assignment of an if turned into a select.
template <class U>
[[gnu::always_inline]] inline void store_if(std::uint32_t* d, const std::uint32_t* a,
                                            const std::uint32_t* cond, const std::uint32_t* r) {
  const std::uint32_t* exec = r + static_cast<std::size_t>(kExecSlot) * kBlockLanes;
  for (int i = 0; i < kBlockLanes; i += kWidth<U>)
    put(d + i, select(load<U>(exec + i) & load<U>(cond + i), load<U>(a + i), load<U>(d + i)));
}

// exec = fn(exec, a[, b]); returns whether a lane is live, and keeps `exec_full` up to date.
template <class U, class State, class Fn>
[[gnu::always_inline]] inline bool mask(std::uint32_t* exec, const std::uint32_t* a, const std::uint32_t* b,
                                        State& state, Fn fn) {
  U any = splat<U>(0), all = splat<U>(~0u);
  for (int i = 0; i < kBlockLanes; i += kWidth<U>) {
    const U m = fn(load<U>(a + i), load<U>(b + i));
    put(exec + i, m);
    any |= m, all &= m;
  }
  if constexpr (kWidth<U> == 1) {
    state.exec_full = all == ~0u;
    return any != 0;
  } else {
    state.exec_full = detail::lane_bits(std::bit_cast<detail::IntLanes>(all)) == 0xffu;
    return detail::lane_bits(std::bit_cast<detail::IntLanes>(any)) != 0;
  }
}
template <class U, class State>
[[gnu::always_inline]] inline bool narrow(std::uint32_t* exec, const std::uint32_t* cond, State& state) {
  return mask<U>(exec, exec, cond, state, [](U e, U c) RASTER_LANES_INLINE { return e & c; });
}
template <class U, class State>
[[gnu::always_inline]] inline void widen(std::uint32_t* exec, const std::uint32_t* a, State& state) {
  mask<U>(exec, exec, a, state, [](U e, U x) RASTER_LANES_INLINE { return e | x; });
}
template <class U, class State>
[[gnu::always_inline]] inline void widen_and_not(std::uint32_t* exec, const std::uint32_t* saved,
                                                 const std::uint32_t* cond, State& state) {
  for (int i = 0; i < kBlockLanes; i += kWidth<U>)
    put(exec + i, load<U>(exec + i) | (load<U>(saved + i) & ~load<U>(cond + i)));
  state.exec_full = all_lanes<U>(exec);
}
template <class U, class State>
[[gnu::always_inline]] inline void widen_and(std::uint32_t* exec, const std::uint32_t* a,
                                             const std::uint32_t* b, State& state) {
  for (int i = 0; i < kBlockLanes; i += kWidth<U>)
    put(exec + i, load<U>(exec + i) | (load<U>(a + i) & load<U>(b + i)));
  state.exec_full = all_lanes<U>(exec);
}
// acc |= exec; exec = 0.
template <class U, class State>
[[gnu::always_inline]] inline void leave(std::uint32_t* acc, std::uint32_t* exec, State& state) {
  for (int i = 0; i < kBlockLanes; i += kWidth<U>) put(acc + i, load<U>(acc + i) | load<U>(exec + i));
  std::memset(exec, 0, kBlockLanes * 4);
  state.exec_full = false;
}
// acc |= exec & cond; exec &= ~cond: the lanes for which cond holds leave.
template <class U, class State>
[[gnu::always_inline]] inline void leave_if(std::uint32_t* acc, std::uint32_t* exec,
                                            const std::uint32_t* cond, State& state) {
  for (int i = 0; i < kBlockLanes; i += kWidth<U>)
    put(acc + i, load<U>(acc + i) | (load<U>(exec + i) & load<U>(cond + i)));
  mask<U>(exec, exec, cond, state, [](U e, U c) RASTER_LANES_INLINE { return e & ~c; });
}

// exits |= exec & ~cond; exec &= cond; whether a lane is live.
template <class U, class State>
[[gnu::always_inline]] inline bool loop_test(std::uint32_t* exits, std::uint32_t* exec,
                                             const std::uint32_t* cond, State& state) {
  for (int i = 0; i < kBlockLanes; i += kWidth<U>)
    put(exits + i, load<U>(exits + i) | (load<U>(exec + i) & ~load<U>(cond + i)));
  return narrow<U>(exec, cond, state);
}

// A comparison into a mask slot (lanes2's shape: the mask's bits are the lane type's).
template <class T, int kUniform = 0, class Fn>
[[gnu::always_inline]] inline void compare(std::uint32_t* d, const std::uint32_t* a, const std::uint32_t* b,
                                           Fn fn) {
  const T y0 = load<T>(b);
  for (int i = 0; i < kBlockLanes; i += kWidth<T>)
    put(d + i, fn(load<T>(a + i), kUniform & 1 ? y0 : load<T>(b + i)));
}

}  // namespace raster::shader::run
