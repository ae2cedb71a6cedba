// One visitor of a std::variant made of one lambda per alternative:
//   std::visit(overloaded{[](const A&) {...}, [](const B&) {...}}, v)
// With no catch-all overload, an alternative left out does not compile.
#pragma once

namespace pita {

template <class... Visitors>
struct overloaded : Visitors... {
  using Visitors::operator()...;
};
template <class... Visitors>
overloaded(Visitors...) -> overloaded<Visitors...>;

}  // namespace pita
