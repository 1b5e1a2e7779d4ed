// SPDX-License-Identifier: BSD-3-Clause
/* mhplan: reading input files (worlds, scenarios, campaigns, grids) safely: only regular files are opened
   for reading (a FIFO would block forever, /dev/zero never ends), and never more than a limit is read. */
#ifndef MHPLAN_IO_INPUT_FILE_H
#define MHPLAN_IO_INPUT_FILE_H

#include <cstddef>
#include <string>

namespace mhplan
{
    /** \brief The largest grid file (.map, .pgm) read whole: 256 MiB (a 16384^2 map is 268 MB). */
    constexpr std::size_t kMaxGridFileBytes = std::size_t{256} << 20;

    /** \brief Throw InputError "PATH: WHY" unless \e path names a regular file (symbolic links followed):
        missing, a symbolic-link loop, a directory, a FIFO, a device or a socket are each refused with their
        own message. \e what names the kind of file ("world file"). Never blocks. */
    void requireRegularFile(const std::string &path, const std::string &what);

    /** \brief The whole contents of the regular file \e path, refused (InputError naming the file and the
        limit) when it holds more than \e maxBytes; at most \e maxBytes + 1 bytes are ever read, so a file
        that grows while it is read cannot exhaust memory. The file is opened without blocking and checked
        to be regular before any byte is read (see requireRegularFile). */
    std::string readInputFile(const std::string &path, std::size_t maxBytes, const std::string &what);
} // namespace mhplan

#endif
