// SPDX-License-Identifier: BSD-3-Clause
#include "benchmarks/ChildProcess.h"

#include "src/base/World.h"

#include <ompl/util/Console.h>
#include <ompl/util/RandomNumbers.h>

#include <poll.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstring>
#include <ctime>
#include <iostream>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace mhplan::bench::detail
{
    double secondsSince(Clock::time_point t0)
    {
        return std::chrono::duration<double>(Clock::now() - t0).count();
    }

    double processCpuSeconds()
    {
        timespec ts{};
        if (::clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts) != 0)
            return 0.0;
        return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
    }

    std::string encodeMap(const std::map<std::string, std::string> &m)
    {
        std::string out;
        for (const auto &kv : m)
            out += kv.first + kFieldSep + kv.second + kRecordSep;
        return out;
    }

    std::map<std::string, std::string> decodeMap(const std::string &s)
    {
        std::map<std::string, std::string> m;
        std::size_t pos = 0;
        while (pos < s.size())
        {
            const std::size_t end = s.find(kRecordSep, pos);
            const std::string rec = s.substr(pos, end == std::string::npos ? std::string::npos : end - pos);
            const std::size_t f = rec.find(kFieldSep);
            if (f != std::string::npos)
                m[rec.substr(0, f)] = rec.substr(f + 1);
            if (end == std::string::npos)
                break;
            pos = end + 1;
        }
        return m;
    }

    std::vector<std::string> splitOn(const std::string &s, char sep)
    {
        std::vector<std::string> out;
        std::size_t pos = 0;
        while (pos <= s.size())
        {
            const std::size_t end = s.find(sep, pos);
            if (end == std::string::npos)
            {
                if (pos < s.size())
                    out.push_back(s.substr(pos));
                break;
            }
            out.push_back(s.substr(pos, end - pos));
            pos = end + 1;
        }
        return out;
    }
    void writeAll(int fd, const std::string &data)
    {
        std::size_t done = 0;
        while (done < data.size())
        {
            const ssize_t n = ::write(fd, data.data() + done, data.size() - done);
            if (n < 0 && errno == EINTR)
                continue;
            if (n <= 0)
                return; // the reader is gone; nothing sensible left to do
            done += static_cast<std::size_t>(n);
        }
    }

    void sendMessage(int fd, char type, std::size_t index, const std::string &payload)
    {
        std::ostringstream head;
        head << type << ' ' << index << ' ' << payload.size() << '\n';
        writeAll(fd, head.str() + payload);
    }

    bool MessageReader::next(Message &m)
    {
        const std::size_t nl = buffer_.find('\n');
        if (nl == std::string::npos)
            return false;
        std::istringstream head(buffer_.substr(0, nl));
        std::size_t bytes = 0;
        head >> m.type >> m.index >> bytes;
        if (buffer_.size() < nl + 1 + bytes)
            return false;
        m.payload = buffer_.substr(nl + 1, bytes);
        buffer_.erase(0, nl + 1 + bytes);
        return true;
    }

    ChildProcess::ChildProcess(const std::function<void(int fd)> &body, const std::vector<int> &closeInChild)
    {
        int fds[2];
        if (::pipe(fds) != 0)
            throw std::runtime_error(std::string("pipe: ") + std::strerror(errno));
        // Flush first so that buffered text is not written twice.
        std::cout.flush();
        std::cerr.flush();
        pid_ = ::fork();
        if (pid_ < 0)
        {
            ::close(fds[0]);
            ::close(fds[1]);
            throw std::runtime_error(std::string("fork: ") + std::strerror(errno));
        }
        if (pid_ == 0)
        {
            ::close(fds[0]);
            ::prctl(PR_SET_PDEATHSIG, SIGKILL);
            const rlimit noCore{0, 0}; // a crashing run leaves no core file behind
            ::setrlimit(RLIMIT_CORE, &noCore);
            for (int fd : closeInChild)
                ::close(fd);
            body(fds[1]);
            ::_exit(5); // body must not return
        }
        ::close(fds[1]);
        fd_ = fds[0];
    }

    ChildProcess::~ChildProcess()
    {
        if (!reaped_)
        {
            kill();
            wait();
        }
    }

    bool ChildProcess::read(const std::function<void(const Message &)> &onMessage)
    {
        char buf[65536];
        ssize_t n;
        do
            n = ::read(fd_, buf, sizeof(buf));
        while (n < 0 && errno == EINTR);
        if (n <= 0)
            return false;
        reader_.feed(buf, static_cast<std::size_t>(n));
        Message m;
        while (reader_.next(m))
            onMessage(m);
        return true;
    }

    void ChildProcess::kill()
    {
        if (!reaped_)
            ::kill(pid_, SIGKILL);
    }

    int ChildProcess::wait()
    {
        int status = 0;
        if (reaped_)
            return status;
        if (fd_ >= 0)
            ::close(fd_);
        fd_ = -1;
        while (::waitpid(pid_, &status, 0) < 0 && errno == EINTR)
        {
        }
        reaped_ = true;
        return status;
    }

    ChildOutcome runChildProcess(double watchdog, const std::function<void(int)> &body,
                                 const std::function<void(const Message &, double)> &onMessage,
                                 const std::vector<int> &closeInChild)
    {
        ChildProcess child(body, closeInChild);
        ChildOutcome out;
        const Clock::time_point runStart = Clock::now();
        Clock::time_point last = runStart;
        const auto handle = [&](const Message &m)
        {
            last = Clock::now();
            if (m.type == 'X')
                out.error = m.payload;
            else
                onMessage(m, secondsSince(runStart));
        };
        while (true)
        {
            pollfd pfd{child.fd(), POLLIN, 0};
            const int r = ::poll(&pfd, 1, 200);
            if (r < 0 && errno == EINTR)
                continue;
            if (r == 0)
            {
                if (secondsSince(last) > watchdog)
                {
                    child.kill();
                    out.killed = true;
                    break;
                }
                continue;
            }
            if (!child.read(handle))
                break;
        }
        out.status = child.wait();
        out.elapsed = std::min(secondsSince(last), out.killed ? watchdog : 1e9);
        out.runSeconds = secondsSince(runStart);
        return out;
    }

    void seedRunProcess(std::uint32_t seed)
    {
        const ompl::msg::LogLevel level = ompl::msg::getLogLevel();
        ompl::msg::setLogLevel(ompl::msg::LOG_NONE);
        ompl::RNG::setSeed(seed);
        ompl::msg::setLogLevel(level);
    }

    /** The end of a run process: run \e body; an exception is reported on \e fd as an 'X' message
        (exit code 3), then the process exits without running destructors. */
    [[noreturn]] void finishRunChild(int fd, const std::function<void()> &body)
    {
        int code = 0;
        try
        {
            body();
        }
        catch (const std::exception &e)
        {
            sendMessage(fd, 'X', 0, e.what());
            code = 3;
        }
        catch (...)
        {
            sendMessage(fd, 'X', 0, "unknown exception");
            code = 3;
        }
        ::close(fd);
        ::_exit(code);
    }

    void checkInChildProcess(const std::function<std::string()> &check, const std::string &what)
    {
        const ChildOutcome outcome = runChildProcess(
            std::numeric_limits<double>::infinity(),
            [&](int fd)
            {
                std::string error;
                try
                {
                    ompl::msg::setLogLevel(ompl::msg::LOG_NONE);
                    error = check();
                }
                catch (const std::exception &ex)
                {
                    error = ex.what();
                }
                if (!error.empty())
                    sendMessage(fd, 'X', 0, error);
                ::close(fd);
                ::_exit(0);
            },
            [](const Message &, double) {});
        if (!outcome.error.empty())
            throw InputError(outcome.error);
        if (!WIFEXITED(outcome.status) || WEXITSTATUS(outcome.status) != 0)
            throw std::runtime_error("checking the campaign's " + what + " crashed the checking process");
    }
} // namespace mhplan::bench::detail
