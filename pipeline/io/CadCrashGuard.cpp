// Scoped fault-signal guard for OpenCASCADE calls. Based on OCCT's signal conversion
// (OSD::SetSignal, OCC_CATCH_SIGNALS with OCC_CONVERT_SIGNALS, Standard_ErrorHandler); see
// CadCrashGuard.h for why and the contract.
#include "pipeline/io/CadCrashGuard.h"

#include <array>
#include <csignal>
#include <mutex>

#include <OSD.hxx>
#include <OSD_Signal.hxx>
#include <Standard_ErrorHandler.hxx>
#include <Standard_Failure.hxx>

#ifndef OCC_CONVERT_SIGNALS
#error "OCCT signal conversion needs OCC_CONVERT_SIGNALS (set by OpenCASCADE's CMake targets)"
#endif

namespace hlod::cad {

namespace {

constexpr std::array<int, 4> kSignals{SIGSEGV, SIGBUS, SIGFPE, SIGILL};
using Actions = std::array<struct sigaction, kSignals.size()>;

thread_local int tGuardDepth = 0; // guarded calls running on this thread

std::mutex gInstallMutex;
int gGuardedCalls = 0; // guarded calls running on all threads
Actions gPrevious{};   // handlers before ours were installed
Actions gOcct{};       // OCCT's fault handlers, captured once

std::size_t slotOf(int signal) {
    for (std::size_t i = 0; i < kSignals.size(); ++i) {
        if (kSignals[i] == signal) return i;
    }
    return 0;
}

void forward(const struct sigaction& next, int signal, siginfo_t* info, void* context) {
    if ((next.sa_flags & SA_SIGINFO) != 0 && next.sa_sigaction != nullptr) {
        next.sa_sigaction(signal, info, context);
    } else if ((next.sa_flags & SA_SIGINFO) == 0 && next.sa_handler != SIG_DFL &&
               next.sa_handler != SIG_IGN) {
        next.sa_handler(signal);
    } else {
        // Default action: returning re-executes the faulting instruction, which now hits it.
        std::signal(signal, SIG_DFL);
    }
}

extern "C" void onFault(int signal, siginfo_t* info, void* context) {
    if (tGuardDepth > 0) {
        // OCCT's handler longjmps (not siglongjmp) to the innermost OCC_CATCH_SIGNALS, which
        // would leave this signal blocked for the rest of the thread's life.
        sigset_t set;
        sigemptyset(&set);
        sigaddset(&set, signal);
        pthread_sigmask(SIG_UNBLOCK, &set, nullptr);
        forward(gOcct[slotOf(signal)], signal, info, context);
        return;
    }
    forward(gPrevious[slotOf(signal)], signal, info, context);
}

// OSD::SetSignal sets OCCT handlers for many signals (Ctrl-C included) process-wide: keep
// only a copy of its fault handlers and put every disposition back as it was.
void captureOcctHandlers() {
    std::array<struct sigaction, NSIG> saved{};
    std::array<bool, NSIG> known{};
    for (int s = 1; s < NSIG; ++s)
        known[s] = sigaction(s, nullptr, &saved[s]) == 0;
    OSD::SetSignal(OSD_SignalMode_Set, false); // false: no floating-point traps
    for (std::size_t i = 0; i < kSignals.size(); ++i) {
        sigaction(kSignals[i], nullptr, &gOcct[i]);
    }
    for (int s = 1; s < NSIG; ++s) {
        if (known[s]) sigaction(s, &saved[s], nullptr);
    }
}

// Installs onFault while at least one guarded call runs (counted over all threads).
class Installation {
public:
    Installation() {
        const std::lock_guard lock(gInstallMutex);
        static const bool captured = (captureOcctHandlers(), true);
        (void)captured;
        if (gGuardedCalls++ > 0) return;
        struct sigaction action {};
        action.sa_sigaction = onFault;
        action.sa_flags = SA_SIGINFO;
        sigemptyset(&action.sa_mask);
        for (std::size_t i = 0; i < kSignals.size(); ++i) {
            sigaction(kSignals[i], &action, &gPrevious[i]);
        }
    }
    ~Installation() {
        const std::lock_guard lock(gInstallMutex);
        if (--gGuardedCalls > 0) return;
        for (std::size_t i = 0; i < kSignals.size(); ++i) {
            sigaction(kSignals[i], &gPrevious[i], nullptr);
        }
    }
    Installation(const Installation&) = delete;
    Installation& operator=(const Installation&) = delete;
};

struct GuardDepth {
    GuardDepth() { ++tGuardDepth; }
    ~GuardDepth() { --tGuardDepth; }
    GuardDepth(const GuardDepth&) = delete;
    GuardDepth& operator=(const GuardDepth&) = delete;
};

void callCatchingSignals(const std::function<void()>& fn) {
    OCC_CATCH_SIGNALS
    fn();
}

} // namespace

void runGuarded(const std::function<void()>& fn) {
    const Installation installation;
    const GuardDepth depth;
    try {
        callCatchingSignals(fn);
    } catch (const OSD_Signal& e) {
        const char* what = e.GetMessageString();
        throw OcctCrash(std::string("OpenCASCADE crashed on this file (") +
                        (what != nullptr ? what : e.DynamicType()->Name()) +
                        "); the file is probably corrupt");
    }
}

} // namespace hlod::cad
