#pragma once
// The table of contact laws: one list of normal laws and one of tangential laws. Everything that
// names or chooses a law follows from these lists: the names a scenario accepts and the allowed
// values its errors list, the laws' identifiers, the dispatch to the concrete types (so that the
// per-contact code has no virtual call), and the parametrised law tests. A new law is one struct
// (normal_laws.hpp, tangential_laws.hpp), one entry here and its analytic test.
#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <tuple>
#include <type_traits>
#include <utility>

#include "talus/contact_force.hpp"
#include "talus/error.hpp"
#include "talus/normal_laws.hpp"
#include "talus/tangential_laws.hpp"

namespace talus {

template <class... Laws> struct LawList {
  static constexpr std::size_t size = sizeof...(Laws);
  /// The law at position I.
  template <std::size_t I> using at = std::tuple_element_t<I, std::tuple<Laws...>>;
  static constexpr std::array<std::string_view, size> names{Laws::name...};
};

using NormalLaws = LawList<LinearSpringDashpot, HertzViscoelastic>;
using TangentialLaws = LawList<ViscousCoulomb, CundallStrack, MindlinNoSlip, Frictionless>;

/// A law chosen at run time: its position in NormalLaws or TangentialLaws.
enum class NormalLaw : std::uint8_t {};
enum class TangentialLaw : std::uint8_t {};

namespace law_table_detail {
template <class Law, class... Laws> constexpr std::size_t index_in(LawList<Laws...>) {
  constexpr std::array<bool, sizeof...(Laws)> same{std::is_same_v<Law, Laws>...};
  for (std::size_t k = 0; k < same.size(); ++k)
    if (same[k]) return k;
  return sizeof...(Laws);
}
template <class Law> constexpr auto id_of() {
  if constexpr (index_in<Law>(NormalLaws{}) < NormalLaws::size)
    return NormalLaw{static_cast<std::uint8_t>(index_in<Law>(NormalLaws{}))};
  else {
    static_assert(index_in<Law>(TangentialLaws{}) < TangentialLaws::size, "not a law of the table");
    return TangentialLaw{static_cast<std::uint8_t>(index_in<Law>(TangentialLaws{}))};
  }
}
template <class Id>
using List = std::conditional_t<std::is_same_v<Id, NormalLaw>, NormalLaws, TangentialLaws>;
// f.template operator()<L>() for the law L at position `index` of the list (the last law for an
// index beyond it: ids come from the table, so that does not happen)
template <class F, class First, class... Rest>
decltype(auto) call_with(std::size_t index, LawList<First, Rest...>, F&& f) {
  if constexpr (sizeof...(Rest) == 0) {
    return f.template operator()<First>();
  } else {
    if (index == 0) return f.template operator()<First>();
    return call_with(index - 1, LawList<Rest...>{}, std::forward<F>(f));
  }
}
} // namespace law_table_detail

/// The identifier of law type L: law_id<HertzViscoelastic> is a NormalLaw, law_id<CundallStrack>
/// a TangentialLaw.
template <class L> inline constexpr auto law_id = law_table_detail::id_of<L>();

/// A law's name, as scenarios spell it.
template <class Id> std::string_view name_of(Id law) {
  const auto& names = law_table_detail::List<Id>::names;
  const auto k = static_cast<std::size_t>(law);
  return k < names.size() ? names[k] : std::string_view{"?"};
}
/// The names of every law of the kind, as "a, b, c": an error's allowed values.
template <class Id> std::string law_names() {
  std::string out;
  for (std::string_view n : law_table_detail::List<Id>::names)
    out += (out.empty() ? "" : ", ") + std::string(n);
  return out;
}
/// The law of that name, if there is one.
template <class Id> std::optional<Id> find_law(std::string_view name) {
  const auto& names = law_table_detail::List<Id>::names;
  for (std::size_t k = 0; k < names.size(); ++k)
    if (names[k] == name) return Id{static_cast<std::uint8_t>(k)};
  return std::nullopt;
}
/// Like find_law; throws InvalidArgument listing the allowed names for an unknown one.
inline NormalLaw parse_normal_law(std::string_view name) {
  if (auto law = find_law<NormalLaw>(name)) return *law;
  throw InvalidArgument("unknown normal law '" + std::string(name) +
                        "'; allowed: " + law_names<NormalLaw>());
}
inline TangentialLaw parse_tangential_law(std::string_view name) {
  if (auto law = find_law<TangentialLaw>(name)) return *law;
  throw InvalidArgument("unknown tangential law '" + std::string(name) +
                        "'; allowed: " + law_names<TangentialLaw>());
}

/// Calls f.template operator()<N>() with the normal law's type.
template <class F> decltype(auto) with_normal_law(NormalLaw n, F&& f) {
  return law_table_detail::call_with(static_cast<std::size_t>(n), NormalLaws{}, std::forward<F>(f));
}
/// Calls f.template operator()<T>() with the tangential law's type.
template <class F> decltype(auto) with_tangential_law(TangentialLaw t, F&& f) {
  return law_table_detail::call_with(static_cast<std::size_t>(t), TangentialLaws{},
                                     std::forward<F>(f));
}
/// Calls f.template operator()<N, T>() with both laws' types.
template <class F> decltype(auto) with_contact_law(NormalLaw n, TangentialLaw t, F&& f) {
  return with_normal_law(n, [&]<class N>() -> decltype(auto) {
    return with_tangential_law(
        t, [&]<class T>() -> decltype(auto) { return f.template operator()<N, T>(); });
  });
}

/// What is wrong with a material for the pair of laws ("" if nothing): the normal law's
/// complaint first, then the tangential law's. `d`: the linear law's damping convention.
inline std::string material_error(NormalLaw n, TangentialLaw t, const Material& m,
                                  LinearDamping d = LinearDamping::never_attractive) {
  std::string problem = with_normal_law(n, [&]<class N>() { return N::material_error(m, d); });
  if (problem.empty())
    problem = with_tangential_law(t, [&]<class T>() { return T::material_error(m); });
  return problem;
}

/// Whether the tangential law keeps a per-contact history (a spring's stretch).
inline bool keeps_history(TangentialLaw t) {
  return with_tangential_law(t, []<class T>() { return T::has_history; });
}
/// Whether the tangential law has friction (every law but `none`).
inline bool has_friction(TangentialLaw t) {
  return with_tangential_law(t, []<class T>() { return T::has_friction; });
}
/// The names of the tangential laws without history, as "a, b": what the LAMMPS package allows.
inline std::string history_free_tangential_names() {
  std::string names;
  for (const std::string_view n : TangentialLaws::names) {
    if (keeps_history(parse_tangential_law(n))) continue;
    names.append(names.empty() ? "" : ", ").append(n);
  }
  return names;
}

} // namespace talus
