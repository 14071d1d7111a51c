#include "common/Error.h"

namespace drytwin {

int exitCodeFor(ErrorKind kind) {
    switch (kind) {
    case ErrorKind::Usage:
        return 2;
    case ErrorKind::BadInput:
        return 3;
    case ErrorKind::Numerical:
        return 4;
    case ErrorKind::Cancelled:
        return 130;
    }
    return 1;
}

Error invalidOption(const std::string& option, const std::string& reason) {
    return Error{ErrorKind::Usage, option, reason, ErrorCode::InvalidOption, {option, reason}};
}

Error cancelledError(const std::string& stage) {
    return Error{ErrorKind::Cancelled, stage, "cancelled by the user", ErrorCode::Cancelled, {stage}};
}

} // namespace drytwin
