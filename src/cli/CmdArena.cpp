// SPDX-License-Identifier: BSD-3-Clause
/* mhplan arena DB: serve OMPL's Planner Arena (R/Shiny) on a benchmark database. The app comes from
   scripts/arena/install.sh (Debian's installed app where it runs, else a private patched copy); it runs as an
   R child in its own process group; SIGINT, SIGTERM and SIGHUP are forwarded to it and it is reaped before
   mhplan exits. */
#include "src/cli/Commands.h"

#include "benchmarks/Database.h"
#include "src/cli/Args.h"
#include "src/cli/Help.h"

#include <arpa/inet.h>
#include <fcntl.h>
#include <netdb.h>
#include <netinet/in.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <thread>

namespace fs = std::filesystem;

namespace mhplan::cli
{
    namespace
    {
        volatile sig_atomic_t gSignal = 0;

        void onSignal(int sig)
        {
            gSignal = sig;
        }

        /** The install script: $MHPLAN_ARENA_SCRIPTS/install.sh, the installed share/mhplan/arena, or the
            source tree's scripts/arena. */
        std::string installScript()
        {
            if (const char *env = std::getenv("MHPLAN_ARENA_SCRIPTS"))
                return (fs::path(env) / "install.sh").string();
            std::error_code ec;
            const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
            if (!ec)
            {
                const fs::path installed =
                    exe.parent_path().parent_path() / MHPLAN_INSTALLED_ARENA_DIR / "install.sh";
                if (fs::exists(installed))
                    return installed.string();
            }
            return (fs::path(MHPLAN_ARENA_SCRIPTS_DIR) / "install.sh").string();
        }

        /** A benchmark database that Planner Arena can open: an SQLite file with the tables its server.R
            reads. Throws InputError otherwise, before anything starts. */
        void checkDatabase(const std::string &path)
        {
            std::error_code ec;
            if (!fs::exists(path, ec))
                throw InputError("mhplan arena: " + path + ": no such file");
            if (!fs::is_regular_file(path, ec))
                throw InputError("mhplan arena: " + path + ": not a regular file");
            std::ifstream in(path, std::ios::binary);
            char magic[16] = {};
            if (!in || !in.read(magic, sizeof magic) || std::memcmp(magic, "SQLite format 3", 16) != 0)
                throw InputError("mhplan arena: " + path +
                                 ": not an SQLite database (make one with 'mhplan bench CAMPAIGN')");
            bench::detail::Database db(path);
            std::string missing;
            for (const char *table : {"experiments", "plannerConfigs", "runs", "progress", "enums"})
                if (!db.hasTable(table))
                    missing += std::string(missing.empty() ? "" : ", ") + table;
            if (!missing.empty())
                throw InputError("mhplan arena: " + path + ": not an OMPL benchmark database (no table " +
                                 missing + "; make one with 'mhplan bench CAMPAIGN')");
        }

        /** Run the install script; its last line of output is the app directory. */
        std::string arenaApp(bool install)
        {
            const std::string script = installScript();
            if (!fs::exists(script))
                throw InputError("mhplan arena: cannot find " + script +
                                 " (set MHPLAN_ARENA_SCRIPTS to the directory holding install.sh)");
            // No shell: the script's path is one argument whatever characters it holds.
            std::vector<std::string> args{"bash", script};
            if (!install)
                args.push_back("--check");
            int pipeFd[2];
            if (::pipe2(pipeFd, O_CLOEXEC) != 0)
                throw InputError("mhplan arena: cannot run " + script + ": " + std::strerror(errno));
            std::cout.flush();
            const pid_t child = ::fork();
            if (child < 0)
                throw InputError("mhplan arena: cannot run " + script + ": " + std::strerror(errno));
            if (child == 0)
            {
                ::dup2(pipeFd[1], 1);
                std::vector<char *> cargs;
                for (auto &a : args)
                    cargs.push_back(a.data());
                cargs.push_back(nullptr);
                ::execvp(cargs[0], cargs.data());
                ::_exit(127);
            }
            ::close(pipeFd[1]);
            std::string out;
            char buf[512];
            for (ssize_t n; (n = ::read(pipeFd[0], buf, sizeof buf)) != 0;)
            {
                if (n < 0 && errno == EINTR)
                    continue;
                if (n < 0)
                    break;
                out.append(buf, static_cast<std::size_t>(n));
            }
            ::close(pipeFd[0]);
            int status = 0;
            while (::waitpid(child, &status, 0) < 0 && errno == EINTR)
            {
            }
            while (!out.empty() && out.back() == '\n')
                out.pop_back();
            const std::string app =
                out.substr(out.rfind('\n') == std::string::npos ? 0 : out.rfind('\n') + 1);
            if (status != 0 || app.empty() || !fs::exists(fs::path(app) / "server.R"))
                throw InputError("mhplan arena: Planner Arena is not available (" + script +
                                 " failed; see its message above)");
            return app;
        }

        /** A private app directory for this database: the app's files linked, www/benchmark.db (the app's
            default database) linked to \e db. */
        std::string sessionDir(const std::string &app, const std::string &db)
        {
            const char *tmp = std::getenv("TMPDIR");
            std::string tmpl = std::string(tmp && *tmp ? tmp : "/tmp") + "/mhplan-arena-XXXXXX";
            if (!::mkdtemp(tmpl.data()))
                throw InputError("mhplan arena: cannot create a directory from " + tmpl + ": " +
                                 std::strerror(errno));
            const fs::path dir(tmpl);
            for (const auto &e : fs::directory_iterator(app))
                if (e.path().filename() != "www")
                    fs::create_symlink(e.path(), dir / e.path().filename());
            fs::create_directory(dir / "www");
            if (fs::is_directory(fs::path(app) / "www"))
                for (const auto &e : fs::directory_iterator(fs::path(app) / "www"))
                    if (e.path().filename() != "benchmark.db")
                        fs::create_symlink(e.path(), dir / "www" / e.path().filename());
            fs::create_symlink(fs::absolute(db), dir / "www" / "benchmark.db");
            return dir.string();
        }

        /** Resolve \e host:port (numeric or a name); throws InputError naming the option. */
        addrinfo *resolve(const std::string &host, int port)
        {
            addrinfo hints{};
            hints.ai_family = AF_UNSPEC;
            hints.ai_socktype = SOCK_STREAM;
            addrinfo *res = nullptr;
            if (::getaddrinfo(host.c_str(), std::to_string(port).c_str(), &hints, &res) != 0 || !res)
                throw InputError("mhplan arena: --host '" + host + "': cannot resolve it");
            return res;
        }

        /** True when \e host:port can be bound now (nothing listens there). */
        bool portFree(const std::string &host, int port)
        {
            addrinfo *res = resolve(host, port);
            bool ok = false;
            const int s = ::socket(res->ai_family, res->ai_socktype, res->ai_protocol);
            if (s >= 0)
            {
                const int one = 1;
                ::setsockopt(s, SOL_SOCKET, SO_REUSEADDR, &one, sizeof one);
                ok = ::bind(s, res->ai_addr, res->ai_addrlen) == 0;
                ::close(s);
            }
            ::freeaddrinfo(res);
            return ok;
        }

        /** True when something accepts connections on \e host:port (a wildcard host: on loopback). */
        bool listening(std::string host, int port)
        {
            if (host == "0.0.0.0")
                host = "127.0.0.1";
            else if (host == "::")
                host = "::1";
            addrinfo *res = resolve(host, port);
            const int s = ::socket(res->ai_family, res->ai_socktype, res->ai_protocol);
            const bool ok = s >= 0 && ::connect(s, res->ai_addr, res->ai_addrlen) == 0;
            if (s >= 0)
                ::close(s);
            ::freeaddrinfo(res);
            return ok;
        }

        std::string rQuoted(const std::string &s)
        {
            std::string out = "'";
            for (char c : s)
            {
                if (c == '\'' || c == '\\')
                    out += '\\';
                out += c;
            }
            return out + "'";
        }

        /** Ask the child's process group to stop: SIGINT (Shiny stops its server), then SIGTERM, then
            SIGKILL, a few seconds apart; returns the waitpid status. */
        int stopChild(pid_t pid)
        {
            int status = 0;
            for (int sig : {SIGINT, SIGTERM, SIGKILL})
            {
                ::kill(-pid, sig);
                for (int k = 0; k < 50; ++k)
                {
                    if (::waitpid(pid, &status, WNOHANG) == pid)
                        return status;
                    std::this_thread::sleep_for(std::chrono::milliseconds(100));
                }
            }
            ::waitpid(pid, &status, 0);
            return status;
        }
    } // namespace

    const CommandDoc &arenaDoc()
    {
        static const CommandDoc doc{
            "arena DB [--port N] [--host H] [--no-install]",
            "serve OMPL's Planner Arena on a benchmark database; prints the URL, Ctrl-C stops it",
            "Runs Debian's ompl-plannerarena (R/Shiny) where it works as installed, else a private copy "
            "with a patched server.R (scripts/arena/install.sh; $MHPLAN_ARENA_DIR, default "
            "~/.cache/mhplan/arena); installs Debian's R packages on first use. No system file is changed. "
            "A campaign's simulations are in their own database (<database stem>-sim.db).",
            {{"DB", "an SQLite database written by mhplan bench (or ompl_benchmark_statistics)"}},
            {{"--port", "N", "TCP port, 1..65535 (default 8888); refused when in use"},
             {"--host", "H", "address to listen on (default 127.0.0.1; 0.0.0.0 for every interface)"},
             {"--no-install", "", "install nothing; fail when Planner Arena is not installed yet"}},
            {"arena results/seeds.db", "arena results/seeds-sim.db --port 8890"},
            "0 stopped by Ctrl-C (SIGINT) or SIGTERM, 1 bad input or R stopped by itself, 2 internal error"};
        return doc;
    }

    int cmdArena(const Argv &argv)
    {
        const Args args("arena", argv, {{"port", "host"}, {}, {"no-install"}});
        if (args.positional().size() != 1)
            throw InputError("mhplan arena: expected one argument, the benchmark database (DB.db)");
        const std::string db = args.positional()[0];
        const long long port = args.integer("port", 8888);
        if (port < 1 || port > 65535)
            throw InputError("mhplan arena: --port must be in 1..65535 (got " + args.get("port") + ")");
        const std::string host = args.get("host", "127.0.0.1");
        if (host.empty())
            throw InputError("mhplan arena: --host must not be empty (e.g. 127.0.0.1 or 0.0.0.0)");
        checkDatabase(db);
        if (!portFree(host, static_cast<int>(port)))
            throw InputError("mhplan arena: --port " + std::to_string(port) + ": " + host + ":" +
                             std::to_string(port) + " is in use (choose another port)");

        const std::string app = arenaApp(!args.has("no-install"));
        const std::string dir = sessionDir(app, db);
        const std::string expr = "shiny::runApp(" + rQuoted(dir) + ", port = " + std::to_string(port) +
                                 "L, host = " + rQuoted(host) + ", launch.browser = FALSE)";

        struct sigaction sa
        {
        };
        sa.sa_handler = onSignal;
        sigemptyset(&sa.sa_mask);
        struct sigaction oldInt
        {
        }, oldTerm{}, oldHup{};
        ::sigaction(SIGINT, &sa, &oldInt);
        ::sigaction(SIGTERM, &sa, &oldTerm);
        ::sigaction(SIGHUP, &sa, &oldHup);
        std::cout << "Planner Arena: starting on " << db << " (app " << app << ")" << std::endl;
        const pid_t pid = ::fork();
        if (pid < 0)
            throw InputError("mhplan arena: cannot start Rscript: " + std::string(std::strerror(errno)));
        if (pid == 0)
        {
            // Own process group (a terminal's Ctrl-C reaches mhplan, which forwards it), dies with mhplan.
            ::setpgid(0, 0);
            ::prctl(PR_SET_PDEATHSIG, SIGTERM);
            ::signal(SIGINT, SIG_DFL);
            ::signal(SIGTERM, SIG_DFL);
            ::signal(SIGHUP, SIG_DFL);
            const int devnull = ::open("/dev/null", O_RDONLY);
            if (devnull >= 0)
                ::dup2(devnull, 0);
            ::execlp("Rscript", "Rscript", "-e", expr.c_str(), static_cast<char *>(nullptr));
            std::fprintf(stderr, "mhplan arena: cannot run Rscript: %s\n", std::strerror(errno));
            ::_exit(127);
        }
        ::setpgid(pid, pid);

        const std::string url = "http://" + (host.find(':') != std::string::npos ? "[" + host + "]" : host) +
                                ":" + std::to_string(port) + "/";
        bool ready = false;
        int status = 0;
        bool exited = false;
        const auto t0 = std::chrono::steady_clock::now();
        while (gSignal == 0)
        {
            if (::waitpid(pid, &status, WNOHANG) == pid)
            {
                exited = true;
                break;
            }
            if (!ready && listening(host, static_cast<int>(port)))
            {
                ready = true;
                std::cout << "Planner Arena: " << url << "  (Ctrl-C stops it)" << std::endl;
            }
            if (!ready && std::chrono::steady_clock::now() - t0 > std::chrono::seconds(120))
            {
                std::cerr << "mhplan arena: error: Planner Arena did not listen on " << url
                          << " within 120 s\n";
                break;
            }
            std::this_thread::sleep_for(std::chrono::milliseconds(ready ? 200 : 100));
        }
        const int sig = gSignal;
        if (!exited)
            status = stopChild(pid);
        ::sigaction(SIGINT, &oldInt, nullptr);
        ::sigaction(SIGTERM, &oldTerm, nullptr);
        ::sigaction(SIGHUP, &oldHup, nullptr);
        std::error_code ec;
        fs::remove_all(dir, ec);
        if (sig != 0)
        {
            std::cout << "Planner Arena: stopped (" << strsignal(sig) << ")" << std::endl;
            return 0;
        }
        if (exited)
        {
            const std::string how = WIFEXITED(status) ? "exit status " + std::to_string(WEXITSTATUS(status))
                                                      : "signal " + std::to_string(WTERMSIG(status));
            std::cerr << "mhplan arena: error: R stopped " << (ready ? "" : "before Planner Arena listened ")
                      << "(" << how << "; its messages are above)\n";
        }
        return 1;
    }
} // namespace mhplan::cli
