#pragma once
// std::visit over a closed set of types with one lambda per type: a type the lambdas do not
// cover does not compile, where a chain of get_if would let it through to its last branch.
//   std::visit(Overloaded{[](const Disk&) {...}, [](const Wall&) {...}, ...}, obstacle);

namespace csl {

template <class... F>
struct Overloaded : F... {
  using F::operator()...;
};
template <class... F>
Overloaded(F...) -> Overloaded<F...>;

}  // namespace csl
