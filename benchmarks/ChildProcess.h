// SPDX-License-Identifier: BSD-3-Clause
/* mhplan bench: the one protocol between a campaign's processes. A child is forked with a pipe to its
   parent and sends framed messages "<type> <index> <bytes>\n<payload>"; the parent reads them as they come
   and may kill the child when it stays silent too long (the watchdog). Planner runs, simulation runs, the
   experiment processes and the throw-away checking processes all speak it. */
#ifndef MHPLAN_BENCH_CHILD_PROCESS_H
#define MHPLAN_BENCH_CHILD_PROCESS_H

#include <sys/types.h>

#include <chrono>
#include <cstdint>
#include <functional>
#include <map>
#include <string>
#include <vector>

namespace mhplan::bench::detail
{
    using Clock = std::chrono::steady_clock;

    double secondsSince(Clock::time_point t0);

    /** CPU seconds this process has used so far, all its threads (CLOCK_PROCESS_CPUTIME_ID). */
    double processCpuSeconds();

    /** Separators of the payload encodings (never part of a property name or value). */
    constexpr char kFieldSep = '\x1f';
    constexpr char kRecordSep = '\x1e';
    constexpr char kGroupSep = '\x1d';

    std::string encodeMap(const std::map<std::string, std::string> &m);
    std::map<std::string, std::string> decodeMap(const std::string &s);
    /** The parts of \e s between the separators (no empty last part). */
    std::vector<std::string> splitOn(const std::string &s, char sep);

    /** Write all of \e data to \e fd (gives up silently when the reader is gone). */
    void writeAll(int fd, const std::string &data);

    /** One framed message. */
    struct Message
    {
        char type{0};
        std::size_t index{0};
        std::string payload;
    };

    void sendMessage(int fd, char type, std::size_t index, const std::string &payload);

    /** Incremental parser of the message stream. */
    class MessageReader
    {
      public:
        void feed(const char *data, std::size_t n) { buffer_.append(data, n); }
        /** The next complete message, if there is one. */
        bool next(Message &m);

      private:
        std::string buffer_;
    };

    /** A forked child process with a pipe from child to parent. The child dies with its parent, leaves no
        core file behind, closes \e closeInChild and runs \e body with the pipe's write end; body must end
        the process with _exit (if it returns, the child exits with code 5). */
    class ChildProcess
    {
      public:
        ChildProcess(const std::function<void(int fd)> &body, const std::vector<int> &closeInChild = {});
        /** Kills and reaps the child if wait() was not called. */
        ~ChildProcess();
        ChildProcess(const ChildProcess &) = delete;
        ChildProcess &operator=(const ChildProcess &) = delete;

        pid_t pid() const { return pid_; }
        /** The read end of the pipe (for poll). */
        int fd() const { return fd_; }
        /** Read what is available and hand every complete message to \e onMessage; false at the end of
            the stream (the child closed the pipe or ended). */
        bool read(const std::function<void(const Message &)> &onMessage);
        void kill();
        /** Close the pipe and reap the child; returns the waitpid status. */
        int wait();

      private:
        pid_t pid_{-1};
        int fd_{-1};
        bool reaped_{false};
        MessageReader reader_;
    };

    /** How a watched child process ended. */
    struct ChildOutcome
    {
        /** Killed by the watchdog (no message for \c watchdog seconds). */
        bool killed{false};
        /** waitpid status. */
        int status{0};
        /** Text of an 'X' message (an exception in the child). */
        std::string error;
        /** Seconds from the last message (or the start) to the end, capped at the watchdog when killed:
            the time recorded for a crashed run. */
        double elapsed{0.0};
        /** Seconds from the fork to the end. */
        double runSeconds{0.0};
    };

    /** Fork a child that executes \e body(fd) (see ChildProcess), hand each message it sends to
        \e onMessage (with the seconds since the fork) except 'X' (kept as the outcome's error), and kill it
        when it sends nothing for \e watchdog seconds (never when \e watchdog is infinite). */
    ChildOutcome runChildProcess(double watchdog, const std::function<void(int)> &body,
                                 const std::function<void(const Message &, double)> &onMessage,
                                 const std::vector<int> &closeInChild = {});

    /** The end of a run process: run \e body; an exception is reported on \e fd as an 'X' message (exit
        code 3), then the process exits without running destructors. */
    [[noreturn]] void finishRunChild(int fd, const std::function<void()> &body);

    /** Seed OMPL's random number generators for the run about to plan or simulate (a run process runs an
        experiment's runs in sequence, each beginning with this call): every generator the run uses is made
        after this call, so the run is determined by \e seed. The campaign process has
        usually made generators already (parseCampaign builds each planner once to check its parameters), and
        OMPL 1.5.2's setSeed then logs that "random number generation already started" although it reseeds
        its seed generator all the same; that message is muted here. */
    void seedRunProcess(std::uint32_t seed);

    /** Run \e check in a throw-away child process; the message it returns (empty = fine) is thrown here as
        InputError. A crash of the child is a runtime_error naming \e what. */
    void checkInChildProcess(const std::function<std::string()> &check, const std::string &what);
} // namespace mhplan::bench::detail

#endif
