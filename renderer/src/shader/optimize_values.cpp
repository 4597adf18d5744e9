// Value numbering over runs of straight-line code (between control operations and jump targets, where
// every instruction runs after the one before it, on the same lanes). fold_and_hoist sees only slots with
// one definition; this pass follows values through slots written many times: a variable updated at the
// top level of a program, a written-out loop's (lower_loop.cpp) running sums and counters. In a run:
//  - an operation of constants becomes a copy of the constant, which later readers read instead;
//  - an identity (x + 0, x * 1, x * 0) and an operation already computed (same operation, same operand
//    values) become a copy of what they equal;
//  - a reader of a copy reads the copied slot while that slot still holds the value;
//  - a division by a power of two becomes a multiply by its reciprocal (the same bits);
// so that the copies are left without readers, and the dead-code passes that follow take them away. Every
// value is a lane-by-lane function of the run's inputs, so replacing one slot by another that holds the
// same value in every lane changes no bit.
#include <cstddef>
#include <map>
#include <tuple>
#include <unordered_map>

#include "shader/engine.h"
#include "shader/optimize.h"

namespace raster::shader {
namespace {

using ValueNumber = std::uint32_t;

// The bits of 1 / x when x is a power of two whose reciprocal is a normal float too (0 otherwise): then
// a / x and a * (1 / x) are the same real number, rounded the same way, so the multiply (cheaper, and
// fusable into an add) gives the division's bits. Subnormal reciprocals are left alone, as the engine
// flushes them to zero.
std::uint32_t reciprocal_of_power_of_two(std::uint32_t x) {
  const std::uint32_t exponent = (x >> 23) & 0xffu;
  if ((x & 0x7fffffu) != 0 || exponent == 0 || exponent == 0xffu) return 0;
  const std::uint32_t reciprocal = 254u - exponent;  // 2^(e - 127) -> 2^(127 - e), biased: 254 - e
  if (reciprocal == 0 || reciprocal >= 0xffu) return 0;
  return (x & 0x80000000u) | (reciprocal << 23);
}

struct Value {
  bool constant = false;
  std::uint32_t bits = 0;     ///< constant: its bits
  Slot holder = kUnusedSlot;  ///< a slot that held it when last seen (check `number[holder]`)
};

class Numbering {
 public:
  explicit Numbering(Lowered& l) : l_(l), groups_{l}, whole_(whole_groups(l)), number_(l.group_of.size(), 0) {
    for (const auto& [s, b] : l.program.constants)
      if (l.group_size[l.group_of[s]] == 1) canonical_.emplace(b, s), constant_slot_.emplace(s, b);
    values_.emplace_back();  // number 0: none yet
  }

  void run() {
    std::vector<Instr>& code = l_.program.code;
    std::vector<bool> target(code.size() + 1, false);
    for (const Instr& in : code)
      if (in.op == Op::if_begin || in.op == Op::if_else || in.op == Op::loop_test || in.op == Op::loop_back)
        target[in.imm] = true;
    for (std::size_t i = 0; i < code.size(); ++i) {
      if (target[i] || ends_run(code[i].op)) forget();
      if (!ends_run(code[i].op)) instruction(code[i]);
    }
  }

 private:
  // A new run: nothing is known of what slots hold.
  void forget() {
    for (const Slot s : touched_) number_[s] = 0;
    touched_.clear();
    expressions_.clear();
    values_.resize(1);
  }

  ValueNumber add(Value v) {
    values_.push_back(v);
    return static_cast<ValueNumber>(values_.size() - 1);
  }
  ValueNumber constant(std::uint32_t bits) {
    const auto [it, added] = constant_number_.try_emplace(bits, 0);
    if (added || it->second >= values_.size() || !values_[it->second].constant ||
        values_[it->second].bits != bits)
      it->second = add(Value{true, bits, constant_slot(bits)});
    return it->second;
  }
  Slot constant_slot(std::uint32_t bits) {
    auto it = canonical_.find(bits);
    if (it == canonical_.end()) {
      const Slot s = groups_.add(true);
      l_.program.constants.emplace_back(s, bits);
      number_.push_back(0);
      whole_.push_back(false);
      constant_slot_.emplace(s, bits);
      it = canonical_.emplace(bits, s).first;
    }
    return it->second;
  }
  bool tracked(Slot s) const { return !whole_[l_.group_of[s]]; }

  // What slot s holds now: its number (a new one for a value this run has not seen yet).
  ValueNumber number(Slot s) {
    if (const auto c = constant_slot_.find(s); c != constant_slot_.end()) return constant(c->second);
    if (!tracked(s)) return add(Value{});  // read or written as a whole group: never the same twice
    if (number_[s] == 0) set(s, add(Value{false, 0, s}));
    return number_[s];
  }
  void set(Slot s, ValueNumber n) {
    if (!tracked(s)) return;
    number_[s] = n;
    touched_.push_back(s);
    Value& v = values_[n];
    if (!v.constant && (v.holder == kUnusedSlot || number_[v.holder] != n)) v.holder = s;
  }
  // Where value n can be read: a constant's slot, or a slot that still holds it.
  Slot home(ValueNumber n) const {
    const Value& v = values_[n];
    if (v.constant) return v.holder;
    return v.holder != kUnusedSlot && number_[v.holder] == n ? v.holder : kUnusedSlot;
  }

  void instruction(Instr& in) {
    // Operands read where their value lives first (so the copies that carried it lose their readers).
    const unsigned fields = read_fields(in);
    Slot* slot[3] = {&in.a, &in.b, &in.c};
    ValueNumber read[3] = {0, 0, 0};
    for (int k = 0; k < 3; ++k) {
      if (!(fields & (1u << k))) continue;
      read[k] = number(*slot[k]);
      if (const Slot h = home(read[k]); h != kUnusedSlot) *slot[k] = h;
    }
    if (in.op == Op::fdiv && values_[read[1]].constant) {
      if (const std::uint32_t r = reciprocal_of_power_of_two(values_[read[1]].bits); r != 0) {
        read[1] = constant(r);
        in.op = Op::fmul, in.b = constant_slot(r);
      }
    }
    const Operands o = operands(in);
    if (!computable(in.op) || o.write_count != 1 || in.op == Op::mov) {
      if (in.op == Op::mov) return set(in.d, read[0]);
      for (int k = 0; k < o.write_count; ++k) clobber(o.writes[k]);
      if (o.writes_group) clobber(in.d);
      return;
    }
    const ValueNumber n = value_of(in, fields, read);
    if (const Slot h = home(n); h != kUnusedSlot && h != in.d) in = Instr{.op = Op::mov, .d = in.d, .a = h};
    set(in.d, n);
  }

  // The number of what a computable instruction gives.
  ValueNumber value_of(const Instr& in, unsigned fields, const ValueNumber read[3]) {
    bool all_constant = true;
    for (int k = 0; k < 3; ++k)
      if (fields & (1u << k)) all_constant &= values_[read[k]].constant;
    if (all_constant) {
      const auto bits = [&](int k) { return fields & (1u << k) ? values_[read[k]].bits : 0u; };
      return constant(evaluate_instruction(in, bits(0), bits(1), bits(2))[0]);
    }
    const Slot same = identity(in, [&](Slot s, std::uint32_t bits) {
      const ValueNumber n = s == in.a ? read[0] : s == in.b ? read[1] : s == in.c ? read[2] : 0;
      return n != 0 && values_[n].constant && values_[n].bits == bits;
    });
    if (same != kUnusedSlot) return same == in.a ? read[0] : same == in.b ? read[1] : read[2];
    ValueNumber a = read[0], b = read[1];
    if (commutes(in.op) && b < a) std::swap(a, b);
    const auto [it, added] = expressions_.try_emplace({in.op, in.flags, a, b, read[2], in.imm}, 0);
    if (added || home(it->second) == kUnusedSlot) it->second = add(Value{});
    return it->second;
  }

  // Slot s (and its group, for a whole one) now holds a value nothing else is known to hold.
  void clobber(Slot s) {
    if (tracked(s)) set(s, add(Value{}));
  }

  Lowered& l_;
  Groups groups_;
  std::vector<bool> whole_;
  std::vector<ValueNumber> number_;  ///< per slot: what it holds in this run (0: not seen yet)
  std::vector<Slot> touched_;
  std::vector<Value> values_;
  std::unordered_map<std::uint32_t, Slot> canonical_;      ///< constant bits -> their slot
  std::unordered_map<Slot, std::uint32_t> constant_slot_;  ///< the other way
  std::unordered_map<std::uint32_t, ValueNumber> constant_number_;
  std::map<std::tuple<Op, std::uint8_t, ValueNumber, ValueNumber, ValueNumber, std::uint32_t>, ValueNumber>
      expressions_;
};

}  // namespace

void number_values(Lowered& l) {
  Numbering(l).run();
}

}  // namespace raster::shader
