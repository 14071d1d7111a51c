#pragma once

#include <string>
#include <utility>
#include <variant>
#include <vector>

namespace drytwin {

/// @brief What went wrong, in the categories of the command-line exit codes (CONTRACT.md §2).
enum class ErrorKind {
    Usage,     ///< wrong options or parameters (exit code 2)
    BadInput,  ///< bad data file, model file or parameter value (exit code 3)
    Numerical, ///< a solver failed in a way the message explains (exit code 4)
    Cancelled  ///< the user stopped the work (exit code 130)
};

/// @brief What went wrong, for front ends that word errors in the user's language
/// (ARCHITECTURE.md rule 11). Each code documents its Error::args in order; Unspecified has
/// none, and the English message is all there is.
enum class ErrorCode {
    Unspecified,
    InvalidOption,       ///< {option, reason}
    FileNotFound,        ///< {path}
    DataFileFormat,      ///< {file, line, column, English reason}
    MissingColumn,       ///< {file, column name}
    TextInNumber,        ///< {file, line, column, cell text, column name}
    TimeNotIncreasing,   ///< {file, line, column}
    ModelFileInvalid,    ///< {file, key, English reason}
    UnknownParameter,    ///< {symbol}
    ParameterOutOfRange, ///< {symbol, value, lower, upper}
    NotEnoughData,       ///< {what, rows found}
    NoDataLoaded,        ///< {}
    ModelNotTrained,     ///< {model key}
    SolverFailed,        ///< {stage, English reason}
    NotImplemented,      ///< {feature}
    Cancelled            ///< {stage}
};

/// @brief An error as a value: where it happened and why. The engine never throws across its API.
struct Error {
    Error() = default;
    Error(ErrorKind kind_, std::string place_, std::string reason_, ErrorCode code_ = ErrorCode::Unspecified,
          std::vector<std::string> args_ = {})
        : kind(kind_), place(std::move(place_)), reason(std::move(reason_)), code(code_),
          args(std::move(args_)) {}

    ErrorKind kind = ErrorKind::BadInput;
    std::string place;  ///< "file:line:column", a parameter name, a solver stage ...
    std::string reason; ///< one sentence a process engineer can act on, in English (logs, CLI)
    ErrorCode code = ErrorCode::Unspecified;
    std::vector<std::string> args; ///< the code's arguments, as ErrorCode documents them
    std::vector<Error> causes;     ///< the errors behind this one, e.g. one per rejected file

    /// @brief "place: reason", or just the reason when there is no place.
    std::string message() const { return place.empty() ? reason : place + ": " + reason; }
};

/// @brief Exit code of the contract for an error kind.
int exitCodeFor(ErrorKind kind);

/// @brief The error of work the user stopped at @p stage ("calibrate", "load" ...).
Error cancelledError(const std::string& stage);

/// @brief A wrong option (exit code 2), with ErrorCode::InvalidOption and its arguments.
Error invalidOption(const std::string& option, const std::string& reason);

/// @brief A value or an error. Minimal stand-in for C++23 std::expected.
template <class T> class Expected {
public:
    Expected(T value) : m_v(std::move(value)) {}
    Expected(Error error) : m_v(std::move(error)) {}

    bool ok() const { return std::holds_alternative<T>(m_v); }
    explicit operator bool() const { return ok(); }
    T& value() { return std::get<T>(m_v); }
    const T& value() const { return std::get<T>(m_v); }
    T& operator*() { return value(); }
    const T& operator*() const { return value(); }
    T* operator->() { return &value(); }
    const T* operator->() const { return &value(); }
    const Error& error() const { return std::get<Error>(m_v); }

private:
    std::variant<T, Error> m_v;
};

/// @brief Success or an error, for calls that return nothing else.
class Status {
public:
    Status() = default;
    Status(Error error) : m_error(std::move(error)), m_ok(false) {}
    bool ok() const { return m_ok; }
    explicit operator bool() const { return m_ok; }
    const Error& error() const { return m_error; }

private:
    Error m_error;
    bool m_ok = true;
};

} // namespace drytwin
