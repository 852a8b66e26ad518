#pragma once
// One table of names per enum: the words a case file uses for its values, which are also the
// words the logs, summary.json and the case reader's messages print. Each enum's table sits
// right below the enum (core/physics_options.hpp, case/case_spec.hpp, sph/particle_set.hpp);
// the case reader parses with it (TomlTableReader::choice) and everything else prints with
// name_of(), so a value and its word are written once. Where some messages name a value in
// other words (the kernel as the log's scene summary names it, a particle kind as the set-up
// names its source), that spelling is a second table beside the first (kKernelTypeLabels,
// kParticleKindSources), not a switch elsewhere.
//
// A table's order is the order the case reader lists the words in its messages ("must be one
// of ..."), usually the default first; reordered() gives another listing of the same words.
#include <array>
#include <cstddef>
#include <optional>
#include <string_view>

namespace netsph {

/// One value of an enum and its word.
template <typename E>
struct EnumName {
  std::string_view name;
  E value;
};

/// The word of `value` in `table`; "?" for a value the table lacks.
template <typename E, std::size_t N>
constexpr std::string_view name_of(const std::array<EnumName<E>, N>& table, E value) {
  for (const EnumName<E>& entry : table) {
    if (entry.value == value) return entry.name;
  }
  return "?";
}

/// The value whose word is `name`; nothing for a word the table lacks.
template <typename E, std::size_t N>
constexpr std::optional<E> value_of(const std::array<EnumName<E>, N>& table,
                                    std::string_view name) {
  for (const EnumName<E>& entry : table) {
    if (entry.name == name) return entry.value;
  }
  return std::nullopt;
}

/// The words of `table`, in its order.
template <typename E, std::size_t N>
constexpr std::array<std::string_view, N> names_of(const std::array<EnumName<E>, N>& table) {
  std::array<std::string_view, N> names{};
  for (std::size_t i = 0; i < N; ++i) names[i] = table[i].name;
  return names;
}

/// Every word and every value appears once: what each table is checked for (static_assert).
template <typename E, std::size_t N>
constexpr bool one_to_one(const std::array<EnumName<E>, N>& table) {
  for (std::size_t i = 0; i < N; ++i) {
    if (table[i].name.empty()) return false;
    for (std::size_t j = i + 1; j < N; ++j) {
      if (table[i].name == table[j].name || table[i].value == table[j].value) return false;
    }
  }
  return true;
}

/// The entries of `table` for `order`, in that order: the same words listed another way
/// (a different default first).
template <typename E, std::size_t N, std::size_t M>
constexpr std::array<EnumName<E>, M> reordered(const std::array<EnumName<E>, N>& table,
                                               const E (&order)[M]) {
  std::array<EnumName<E>, M> out{};
  for (std::size_t i = 0; i < M; ++i) out[i] = {name_of(table, order[i]), order[i]};
  return out;
}

}  // namespace netsph
