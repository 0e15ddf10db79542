#include "liggghtsScript.H"

#include <mpi.h>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <fstream>
#include <string>
#include <unistd.h>
#include <vector>

// LIGGGHTS
#include "lammps.h"
#include "input.h"
#include "universe.h"
#include "variable.h"
#include "modify.h"
#include "fix_multisphere.h"
#include "multisphereBodies.H"
#include "update.h"
#include <stdexcept>

namespace
{
    // The command LIGGGHTS is executing: Input::line, a protected member,
    // named through a derived class (it holds the raw text of the current
    // command, continuation lines joined, before variable substitution)
    struct inputAccess : LAMMPS_NS::Input
    {
        static constexpr char* LAMMPS_NS::Input::* currentLine =
            &inputAccess::line;
    };

    LAMMPS_NS::LAMMPS* lmp = nullptr;
    int rank = 0;
    std::string scriptPath;
    std::string logPath;        // empty: no log file

    // An error report has started on this rank: the rest of LIGGGHTS's
    // screen output is its message
    bool inError = false;

    // The screen stream is writing the report to the log stream
    bool fromScreen = false;

    // Ranks > 0: the log file, opened for appending when a report starts
    FILE* rankLog = nullptr;

    // Rank 0: descriptor of the log file (for the crash handler)
    int logFd = -1;

    // The script's commands (continuation lines joined as LIGGGHTS joins
    // them) and the line each starts on
    std::vector<std::pair<std::string, int>> scriptCommands;


    void readScriptCommands()
    {
        std::ifstream is(scriptPath);
        std::string physical, joined;
        int lineNo = 0, start = 0;
        while (std::getline(is, physical))
        {
            ++lineNo;
            if (joined.empty()) start = lineNo;
            size_t end = physical.find_last_not_of(" \t\r\n\v\f");
            if (end != std::string::npos && physical[end] == '&')
            {
                joined += physical.substr(0, end);
                continue;
            }
            joined += (end == std::string::npos) ? "" : physical.substr(0, end + 1);
            scriptCommands.emplace_back(joined, start);
            joined.clear();
        }
    }


    std::string currentCommand()
    {
        if (!lmp || !lmp->input) return std::string();
        const char* line = lmp->input->*inputAccess::currentLine;
        return line ? std::string(line) : std::string();
    }


    // Where the current command comes from, for the report
    std::string where(const std::string& cmd)
    {
        for (const auto& c : scriptCommands)
        {
            if (c.first == cmd)
            {
                return scriptPath + ", line " + std::to_string(c.second);
            }
        }
        return "run from " + scriptPath + " (an included file, a loop or "
            "a command LIGGGHTS runs itself)";
    }


    std::string reportHeader(const char* what, bool crashed = false)
    {
        const std::string cmd(currentCommand());
        std::string s("\n--> foamDEM FATAL ERROR: LIGGGHTS ");
        s += what;
        if (rank > 0) s += " on rank " + std::to_string(rank);
        if (cmd.empty())
        {
            s += " before reading " + scriptPath + "\n";
        }
        else
        {
            s += " in the command\n    " + cmd + "\n    (" + where(cmd) + ")\n";
        }
        if (!logPath.empty())
        {
            s += std::string(crashed ? "    Output" : "    LIGGGHTS's message follows; full output")
               + " in " + logPath + "\n";
        }
        return s;
    }


    // Write part of a report to the log file
    void toLog(const std::string& text)
    {
        if (logPath.empty()) return;
        if (rank == 0)
        {
            if (lmp && lmp->logfile)
            {
                fromScreen = true;
                std::fputs(text.c_str(), lmp->logfile);
                std::fflush(lmp->logfile);
                fromScreen = false;
            }
        }
        else
        {
            if (!rankLog) rankLog = std::fopen(logPath.c_str(), "a");
            if (rankLog)
            {
                std::fputs(text.c_str(), rankLog);
                std::fflush(rankLog);
            }
        }
    }


    // A stream over a file (or over nothing) that writes through at once
    struct stream
    {
        FILE* file;             // nullptr: output discarded
        std::string pending;    // screen: the unfinished line
    };

    ssize_t screenWrite(void* cookie, const char* buf, size_t size)
    {
        stream& s = *static_cast<stream*>(cookie);
        s.pending.append(buf, size);
        size_t eol;
        while ((eol = s.pending.find('\n')) != std::string::npos)
        {
            std::string line(s.pending, 0, eol + 1);
            s.pending.erase(0, eol + 1);
            if (!inError && line.compare(0, 5, "ERROR") == 0)
            {
                inError = true;
                const std::string header(reportHeader("stopped on an error"));
                std::fputs(header.c_str(), stderr);
                toLog(header);
                if (s.file && s.file != stdout) std::fputs(header.c_str(), s.file);
            }
            if (inError)
            {
                // LIGGGHTS 3.8 may follow an error with an uninitialised
                // 'special message' (bytes that are not text): dropped
                bool text = true;
                for (const char c : line)
                {
                    const unsigned char u = c;
                    if ((u < 0x20 && c != '\n' && c != '\t') || u >= 0x7f) text = false;
                }
                if (!text) continue;
                // To stderr instead of a screen on stdout (no duplicate on
                // a terminal); a screen file keeps it as well
                std::fputs(line.c_str(), stderr);
                std::fflush(stderr);
                toLog(line);
                if (s.file && s.file != stdout)
                {
                    std::fputs(line.c_str(), s.file);
                    std::fflush(s.file);
                }
            }
            else if (s.file)
            {
                std::fputs(line.c_str(), s.file);
                std::fflush(s.file);
            }
        }
        return ssize_t(size);
    }

    ssize_t logWrite(void* cookie, const char* buf, size_t size)
    {
        // After an error, LIGGGHTS's own copy of the message (error->all)
        // is dropped: the report is already there
        stream& s = *static_cast<stream*>(cookie);
        if (s.file && (!inError || fromScreen))
        {
            std::fwrite(buf, 1, size, s.file);
            std::fflush(s.file);
        }
        return ssize_t(size);
    }

    int streamClose(void* cookie)
    {
        stream* s = static_cast<stream*>(cookie);
        int status = 0;
        if (s->file)
        {
            if (!s->pending.empty()) std::fputs(s->pending.c_str(), s->file);
            status = (s->file == stdout) ? std::fflush(s->file) : std::fclose(s->file);
        }
        delete s;
        return status;
    }

    FILE* openStream(FILE* file, bool screen)
    {
        cookie_io_functions_t io{nullptr, screen ? screenWrite : logWrite,
            nullptr, streamClose};
        FILE* f = fopencookie(new stream{file, {}}, "w", io);
        if (f) std::setvbuf(f, nullptr, _IOLBF, 0);
        return f;
    }


    void crashHandler(int sig)
    {
        const std::string report
        (
            reportHeader
            (
                (std::string("crashed (signal ") + std::to_string(sig) + ", "
               + strsignal(sig) + ")").c_str(),
                true
            )
        );
        ssize_t ignored = write(2, report.data(), report.size());
        int fd = (rank == 0) ? logFd : -1;
        if (rank > 0 && !logPath.empty())
        {
            fd = open(logPath.c_str(), O_WRONLY | O_APPEND);
        }
        if (fd >= 0) ignored = write(fd, report.data(), report.size());
        (void)ignored;
        std::signal(sig, SIG_DFL);
        std::raise(sig);
    }


    bool isNumber(const char* s)
    {
        char* end = nullptr;
        std::strtod(s, &end);
        return end != s && *end == '\0';
    }


    const char* usage =
        "Usage: foamDEMLiggghts -in SCRIPT [-log FILE|none] [-screen FILE|none]\n"
        "           [-var NAME VALUE...]... [-echo none|screen|log|both]\n"
        "           [-writeBodies FILE] [-readBodies FILE -restartOut FILE]\n"
        "Runs a LIGGGHTS input script (a DEM-only stage) on the ranks mpirun\n"
        "gives it; LIGGGHTS errors reach stderr and the log file.\n"
        "After the script: -writeBodies writes the multisphere bodies' states\n"
        "(multisphereBodies.H); -readBodies (one process) sets the bodies the\n"
        "script made from such a file, sets up, takes the file's step and\n"
        "writes the LIGGGHTS restart -restartOut.\n";


    // A line to LIGGGHTS's screen and log (rank 0)
    void say(const std::string& line)
    {
        if (rank != 0) return;
        for (FILE* f : {lmp->screen, lmp->logfile})
        {
            if (f)
            {
                std::fprintf(f, "%s\n", line.c_str());
                std::fflush(f);
            }
        }
    }


    // After the script: the bodies' states written, or read and written
    // into a restart. Errors end every rank.
    void bodyStates
    (
        const std::string& writeFile,
        const std::string& readFile,
        const std::string& restartOut
    )
    {
        if (writeFile.empty() && readFile.empty()) return;
        std::string what;
        try
        {
            auto* ms = dynamic_cast<LAMMPS_NS::FixMultisphere*>
            (
                lmp->modify->find_fix_style("multisphere", 0)
            );
            if (!ms)
            {
                throw std::runtime_error
                (
                    "the script defines no fix multisphere: no bodies to "
                  + std::string(readFile.empty() ? "write" : "set")
                );
            }
            if (!readFile.empty())
            {
                what = "setting the bodies from " + readFile;
                const long step = Foam::foamDEM::readBodyStates(*lmp, *ms, readFile);
                const std::string part(restartOut + ".part");
                for
                (
                    const std::string& cmd :
                    {
                        std::string("run 0 post no"),
                        "reset_timestep " + std::to_string(step),
                        "write_restart " + part
                    }
                )
                {
                    lmp->input->one(cmd.c_str());
                }
                if (rank == 0 && std::rename(part.c_str(), restartOut.c_str()))
                {
                    throw std::runtime_error("cannot rename " + part);
                }
                say
                (
                    "BODIES: " + std::to_string(ms->n_body_all()) + " set from "
                  + readFile + ", step " + std::to_string(step) + "; restart "
                  + restartOut
                );
            }
            if (!writeFile.empty())
            {
                what = "writing the bodies to " + writeFile;
                const long n = Foam::foamDEM::writeBodyStates(*lmp, *ms, writeFile);
                say
                (
                    "BODIES: " + std::to_string(n) + " written to " + writeFile
                  + ", step " + std::to_string(lmp->update->ntimestep)
                );
            }
        }
        catch (const std::exception& e)
        {
            const std::string report
            (
                "\n--> foamDEM FATAL ERROR: foamDEMLiggghts: " + what
              + (what.empty() ? "" : ": ") + e.what() + "\n"
            );
            std::fputs(report.c_str(), stderr);
            if (rank == 0 && lmp->logfile)
            {
                std::fputs(report.c_str(), lmp->logfile);
                std::fflush(lmp->logfile);
            }
            MPI_Abort(MPI_COMM_WORLD, 1);
        }
    }
}


int Foam::foamDEM::runLiggghtsScript(int argc, char* argv[])
{
    MPI_Init(&argc, &argv);
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);

    // Arguments, as the liggghts executable takes them
    std::string screen, echo, writeBodies, readBodies, restartOut;
    bool hasScreen = false;
    logPath = "log.liggghts";
    std::vector<std::vector<std::string>> vars;
    std::string bad;
    for (int i = 1; i < argc && bad.empty(); ++i)
    {
        const std::string a(argv[i]);
        const bool more = i + 1 < argc;
        if ((a == "-in" || a == "-i") && more) scriptPath = argv[++i];
        else if ((a == "-log" || a == "-l") && more) logPath = argv[++i];
        else if ((a == "-screen" || a == "-sc") && more)
        {
            screen = argv[++i];
            hasScreen = true;
        }
        else if ((a == "-echo" || a == "-e") && more) echo = argv[++i];
        else if (a == "-writeBodies" && more) writeBodies = argv[++i];
        else if (a == "-readBodies" && more) readBodies = argv[++i];
        else if (a == "-restartOut" && more) restartOut = argv[++i];
        else if ((a == "-var" || a == "-v") && i + 2 < argc)
        {
            std::vector<std::string> v{argv[++i]};
            while
            (
                i + 1 < argc
             && (argv[i + 1][0] != '-' || isNumber(argv[i + 1]))
            )
            {
                v.emplace_back(argv[++i]);
            }
            if (v.size() < 2) bad = "-var " + v[0] + " has no value";
            vars.push_back(v);
        }
        else if (a == "-help" || a == "-h")
        {
            if (rank == 0) std::fputs(usage, stdout);
            MPI_Finalize();
            return 0;
        }
        else bad = "unknown or incomplete argument '" + a + "'";
    }
    if (bad.empty() && scriptPath.empty()) bad = "no input script (-in)";
    if (bad.empty() && readBodies.empty() != restartOut.empty())
    {
        bad = "-readBodies and -restartOut go together";
    }
    int readable = 0;
    if (bad.empty() && rank == 0)
    {
        readable = access(scriptPath.c_str(), R_OK) == 0;
    }
    MPI_Bcast(&readable, 1, MPI_INT, 0, MPI_COMM_WORLD);
    if (bad.empty() && !readable)
    {
        bad = "cannot read the input script " + scriptPath;
    }
    if (!bad.empty())
    {
        if (rank == 0)
        {
            std::fprintf(stderr, "--> foamDEM FATAL ERROR: foamDEMLiggghts: %s\n%s",
                bad.c_str(), usage);
        }
        MPI_Finalize();
        return 1;
    }
    if (logPath == "none") logPath.clear();
    readScriptCommands();

    std::vector<std::string> args{"foamDEMLiggghts",
        "-log", logPath.empty() ? std::string("none") : logPath};
    if (hasScreen)
    {
        args.insert(args.end(), {"-screen", screen});
    }
    if (!echo.empty())
    {
        args.insert(args.end(), {"-echo", echo});
    }
    std::vector<char*> argp;
    for (std::string& a : args) argp.push_back(&a[0]);
    argp.push_back(nullptr);

    lmp = new LAMMPS_NS::LAMMPS(int(args.size()), argp.data(), MPI_COMM_WORLD);

    // The screen and log streams write through at once; every rank has a
    // screen (LIGGGHTS 3.8 crashes with none), only rank 0 a visible one
    FILE* screenStream = nullptr;
    if (rank == 0)
    {
        FILE* rawScreen = lmp->screen;
        if (rawScreen) std::fflush(rawScreen);
        screenStream = openStream(rawScreen, true);
        if (lmp->logfile)
        {
            std::fflush(lmp->logfile);
            logFd = fileno(lmp->logfile);
            lmp->logfile = openStream(lmp->logfile, false);
            lmp->universe->ulogfile = lmp->logfile;
        }
    }
    else
    {
        screenStream = openStream(nullptr, true);
    }
    if (!screenStream)
    {
        std::fprintf(stderr, "--> foamDEM FATAL ERROR: foamDEMLiggghts: cannot"
            " open its output streams\n");
        MPI_Abort(MPI_COMM_WORLD, 1);
    }
    lmp->screen = screenStream;
    lmp->universe->uscreen = screenStream;

    for (int sig : {SIGSEGV, SIGBUS, SIGFPE})
    {
        std::signal(sig, crashHandler);
    }

    // -var NAME VALUE...: index-style variables, as liggghts sets them
    for (std::vector<std::string>& v : vars)
    {
        std::vector<char*> values;
        for (size_t k = 1; k < v.size(); ++k) values.push_back(&v[k][0]);
        lmp->input->variable->set(&v[0][0], int(values.size()), values.data());
    }

    lmp->input->file(scriptPath.c_str());
    bodyStates(writeBodies, readBodies, restartOut);

    delete lmp;     // closes the log
    lmp = nullptr;
    std::fclose(screenStream);
    MPI_Finalize();
    return 0;
}
