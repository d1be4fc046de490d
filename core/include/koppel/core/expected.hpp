// A value, or the reason there is none: the return type of every koppel function that can fail
// for a reason worth telling (in place of a bool and a std::string* out-parameter). A small
// stand-in for C++23's std::expected<T, std::string>.
#pragma once

#include <stdexcept>
#include <string>
#include <utility>
#include <variant>

namespace koppel {

template <class T>
class Expected {
 public:
  Expected(T value) : state_(std::in_place_index<0>, std::move(value)) {}  // NOLINT: a value converts
  static Expected Error(std::string why) { return Expected(std::in_place_index<1>, std::move(why)); }

  bool has_value() const { return state_.index() == 0; }
  explicit operator bool() const { return has_value(); }
  // The value; precondition has_value() (std::logic_error otherwise: a bug in the caller).
  const T& value() const {
    if (!has_value()) throw std::logic_error("koppel::Expected: no value: " + std::get<1>(state_));
    return std::get<0>(state_);
  }
  T& value() {
    if (!has_value()) throw std::logic_error("koppel::Expected: no value: " + std::get<1>(state_));
    return std::get<0>(state_);
  }
  const T& operator*() const { return value(); }
  T& operator*() { return value(); }
  const T* operator->() const { return &value(); }
  // Why there is no value; empty when there is one.
  const std::string& error() const {
    static const std::string none;
    return has_value() ? none : std::get<1>(state_);
  }

 private:
  template <size_t I, class U>
  Expected(std::in_place_index_t<I> index, U&& u) : state_(index, std::forward<U>(u)) {}
  std::variant<T, std::string> state_;
};

// Done, or the reason it could not be: for an operation whose result is written elsewhere (into
// an out-parameter reused across calls) or that only checks.
using Outcome = Expected<std::monostate>;
inline Outcome Done() { return std::monostate{}; }

}  // namespace koppel
