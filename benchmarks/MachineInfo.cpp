// SPDX-License-Identifier: BSD-3-Clause
/* mhplan bench: the machine description of OMPL's benchmark logs, without a shell. OMPL 1.5.2's
   ompl::machine::getCPUInfo() runs popen("lscpu") (a /bin/sh and an lscpu process) every time
   ompl::tools::Benchmark::benchmark() is called, i.e. for every run of a campaign, where every run is one
   benchmark call in its own process: two process starts per run, most of a short run's overhead, and a shell
   in a program that otherwise never starts one. mhplan defines that function itself (the dynamic linker
   binds OMPL's calls to the program's definition, docs/conventions.md "No shell"): the same lscpu output,
   read once per process tree by fork and exec with an argument vector and kept. */
#include "benchmarks/ExperimentRuns.h"

#include <ompl/tools/benchmark/MachineSpecs.h>

#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <mutex>
#include <string>

namespace mhplan::bench::detail
{
    namespace
    {
        /** The standard output of `lscpu` (empty when it cannot run), by fork and exec: no shell. */
        std::string runLscpu()
        {
            int fds[2];
            if (::pipe2(fds, O_CLOEXEC) != 0)
                return "";
            const pid_t pid = ::fork();
            if (pid < 0)
            {
                ::close(fds[0]);
                ::close(fds[1]);
                return "";
            }
            if (pid == 0)
            {
                ::dup2(fds[1], 1);
                const int devnull = ::open("/dev/null", O_WRONLY);
                if (devnull >= 0)
                    ::dup2(devnull, 2);
                char *const argv[] = {const_cast<char *>("lscpu"), nullptr};
                ::execvp(argv[0], argv);
                ::_exit(127);
            }
            ::close(fds[1]);
            std::string out;
            char buf[4096];
            for (ssize_t n; (n = ::read(fds[0], buf, sizeof buf)) != 0;)
            {
                if (n < 0 && errno == EINTR)
                    continue;
                if (n < 0)
                    break;
                out.append(buf, static_cast<std::size_t>(n));
            }
            ::close(fds[0]);
            int status = 0;
            while (::waitpid(pid, &status, 0) < 0 && errno == EINTR)
            {
            }
            return WIFEXITED(status) && WEXITSTATUS(status) == 0 ? out : "";
        }
    } // namespace

    const std::string &machineCpuInfo()
    {
        static std::once_flag once;
        static std::string info;
        std::call_once(once, [] { info = runLscpu(); });
        return info;
    }
} // namespace mhplan::bench::detail

/** OMPL's function, defined by the program (see above): its callers in libompl get this one. */
std::string ompl::machine::getCPUInfo()
{
    return mhplan::bench::detail::machineCpuInfo();
}
