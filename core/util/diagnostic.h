// Diagnostic and Result<T>: how anything a user can get wrong (a file, a value, a shader) is
// reported, with a message and a location (file:line:column). Programmer mistakes use
// GLINT_CHECK instead. No exceptions cross this boundary.
#pragma once

#include <cstdio>
#include <cstdlib>
#include <optional>
#include <string>
#include <utility>
#include <variant>

namespace glint {

struct SourceLocation {
    std::string file;  // empty when the input did not come from a file
    int line = 0;      // 1-based; 0 when unknown
    int column = 0;    // 1-based; 0 when unknown
};

struct Diagnostic {
    SourceLocation where;
    std::string message;

    // "file:line:column: message", leaving out the parts that are unknown.
    std::string format() const {
        std::string text;
        if (!where.file.empty()) text += where.file + ":";
        if (where.line > 0) text += std::to_string(where.line) + ":";
        if (where.line > 0 && where.column > 0) text += std::to_string(where.column) + ":";
        if (!text.empty()) text += " ";
        return text + message;
    }
};

inline Diagnostic makeError(std::string message, SourceLocation where = {}) {
    return Diagnostic{std::move(where), std::move(message)};
}

// Either a value or a Diagnostic saying why there is none.
template <class T>
class [[nodiscard]] Result {
public:
    Result(T value) : state_(std::move(value)) {}
    Result(Diagnostic error) : state_(std::move(error)) {}

    bool ok() const { return std::holds_alternative<T>(state_); }
    explicit operator bool() const { return ok(); }
    T& value() & { return std::get<T>(state_); }
    const T& value() const& { return std::get<T>(state_); }
    T&& value() && { return std::get<T>(std::move(state_)); }
    T* operator->() { return &value(); }
    const T* operator->() const { return &value(); }
    T& operator*() & { return value(); }
    const Diagnostic& error() const { return std::get<Diagnostic>(state_); }

private:
    std::variant<T, Diagnostic> state_;
};

// Result for operations that return nothing on success.
struct Done {};
using Status = Result<Done>;
inline Status success() { return Done{}; }

}  // namespace glint

// Programmer mistakes (a broken invariant, not bad input): print and abort, after pbrt's CHECK.
#define GLINT_CHECK(condition)                                                            \
    do {                                                                                  \
        if (!(condition)) {                                                               \
            std::fprintf(stderr, "%s:%d: GLINT_CHECK(%s) failed\n", __FILE__, __LINE__, \
                         #condition);                                                     \
            std::abort();                                                                 \
        }                                                                                 \
    } while (false)
