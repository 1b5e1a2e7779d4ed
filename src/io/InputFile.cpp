// SPDX-License-Identifier: BSD-3-Clause
#include "src/io/InputFile.h"

#include "src/base/World.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace mhplan
{
    namespace
    {
        /** Why \e st (of a file that exists) is not a regular file; "" when it is. */
        std::string notRegular(const struct stat &st)
        {
            if (S_ISREG(st.st_mode))
                return "";
            if (S_ISDIR(st.st_mode))
                return "is a directory";
            if (S_ISFIFO(st.st_mode))
                return "is a FIFO (named pipe)";
            if (S_ISCHR(st.st_mode) || S_ISBLK(st.st_mode))
                return "is a device";
            if (S_ISSOCK(st.st_mode))
                return "is a socket";
            return "is not a regular file";
        }

        [[noreturn]] void refuse(const std::string &path, const std::string &what, const std::string &why)
        {
            throw InputError(path + ": cannot read the " + what + ": " + why +
                             " (only regular files are read)");
        }

        std::string openError(int err)
        {
            if (err == ENOENT)
                return "no such file";
            if (err == ELOOP)
                return "too many levels of symbolic links (a symbolic-link loop?)";
            return std::strerror(err);
        }
    } // namespace

    void requireRegularFile(const std::string &path, const std::string &what)
    {
        struct stat st
        {
        };
        if (::stat(path.c_str(), &st) != 0)
            refuse(path, what, openError(errno));
        const std::string why = notRegular(st);
        if (!why.empty())
            refuse(path, what, why);
    }

    std::string readInputFile(const std::string &path, std::size_t maxBytes, const std::string &what)
    {
        // O_NONBLOCK: opening a FIFO for reading would otherwise wait for a writer forever.
        const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY);
        if (fd < 0)
            refuse(path, what, openError(errno));
        struct stat st
        {
        };
        if (::fstat(fd, &st) != 0)
        {
            const int err = errno;
            ::close(fd);
            refuse(path, what, std::strerror(err));
        }
        const std::string why = notRegular(st);
        if (!why.empty())
        {
            ::close(fd);
            refuse(path, what, why);
        }
        const auto tooLarge = [&]()
        {
            ::close(fd);
            throw InputError(path + ": the " + what + " is larger than " + std::to_string(maxBytes) +
                             " bytes, the limit for this kind of file");
        };
        if (static_cast<unsigned long long>(st.st_size) > maxBytes)
            tooLarge();
        std::string text;
        text.reserve(static_cast<std::size_t>(st.st_size));
        char buf[1 << 16];
        while (true)
        {
            const ssize_t n = ::read(fd, buf, sizeof buf);
            if (n < 0 && (errno == EINTR || errno == EAGAIN))
                continue;
            if (n < 0)
            {
                const int err = errno;
                ::close(fd);
                refuse(path, what, std::strerror(err));
            }
            if (n == 0)
                break;
            if (text.size() + static_cast<std::size_t>(n) > maxBytes)
                tooLarge();
            text.append(buf, static_cast<std::size_t>(n));
        }
        ::close(fd);
        return text;
    }
} // namespace mhplan
