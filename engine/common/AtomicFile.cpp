#include "common/AtomicFile.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <sys/stat.h>
#include <unistd.h>

namespace drytwin {

Status writeFileAtomically(const std::string& path, const std::string& contents) {
    namespace fs = std::filesystem;
    const fs::path target(path);
    const fs::path dir = target.has_parent_path() ? target.parent_path() : fs::path(".");
    std::string tmpl = (dir / ("." + target.filename().string() + ".XXXXXX")).string();
    const int fd = ::mkstemp(tmpl.data());
    if (fd < 0) {
        return Error{ErrorKind::BadInput, path,
                     std::string("cannot create a file here: ") + std::strerror(errno)};
    }
    const char* p = contents.data();
    size_t left = contents.size();
    while (left > 0) {
        const ssize_t n = ::write(fd, p, left);
        if (n < 0) {
            if (errno == EINTR) {
                continue;
            }
            const int err = errno;
            ::close(fd);
            ::unlink(tmpl.c_str());
            return Error{ErrorKind::BadInput, path, std::string("write failed: ") + std::strerror(err)};
        }
        p += n;
        left -= static_cast<size_t>(n);
    }
    if (::fsync(fd) != 0 || ::close(fd) != 0) {
        const int err = errno;
        ::unlink(tmpl.c_str());
        return Error{ErrorKind::BadInput, path,
                     std::string("could not flush the file: ") + std::strerror(err)};
    }
    ::chmod(tmpl.c_str(), 0644);
    if (std::rename(tmpl.c_str(), path.c_str()) != 0) {
        const int err = errno;
        ::unlink(tmpl.c_str());
        return Error{ErrorKind::BadInput, path,
                     std::string("could not replace the file: ") + std::strerror(err)};
    }
    return {};
}

Expected<std::string> readWholeFile(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        return Error{ErrorKind::BadInput, path, std::string("cannot open: ") + std::strerror(errno)};
    }
    std::ostringstream ss;
    ss << in.rdbuf();
    if (in.bad()) {
        return Error{ErrorKind::BadInput, path, "read error"};
    }
    return ss.str();
}

} // namespace drytwin
