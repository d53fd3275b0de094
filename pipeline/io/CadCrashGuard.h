// Turns a hardware fault inside OpenCASCADE (SIGSEGV, SIGBUS, SIGFPE, SIGILL) into a C++
// exception, so a corrupt CAD file gives an error instead of killing the editor.
//
// Why: OCCT 7.6's STEP translator dereferences null handles on files with dangling entity
// references (StepToGeom::MakeVectorWithMagnitude with a deleted VECTOR entity of
// as1-oc-214.stp); no OCCT API reports that as an error.
// How: OCCT's own mechanism (OSD::SetSignal handlers + OCC_CATCH_SIGNALS, Standard_ErrorHandler)
// so the jump lands on the innermost live OCCT error handler and OCCT's handler chain stays
// consistent (jumping past OCCT's handlers with a private siglongjmp corrupts it: the next
// IGES read then crashed). Scoped: OSD::SetSignal is called once only to capture OCCT's fault
// handlers and every signal disposition is put back at once (it also grabs Ctrl-C); ours is
// installed only while a guarded call runs and forwards a fault to OCCT's handler when the
// faulting thread is inside a guarded call, else to the handler that was there before.
//
// Contract for `fn`: after a fault, frames between the fault and the catch point are left
// without running destructors (memory leaks; never take locks inside `fn`). Faults must
// happen on the calling thread (run OCCT single-threaded inside). A stack overflow cannot be
// caught (no alternate signal stack).
#pragma once

#include <functional>
#include <stdexcept>
#include <string>

namespace hlod::cad {

class OcctCrash : public std::runtime_error {
public:
    explicit OcctCrash(const std::string& what) : std::runtime_error(what) {}
};

// Runs fn() on this thread; throws OcctCrash if a fault signal interrupted it and no OCCT
// code inside recovered from it. Exceptions thrown by fn() pass through unchanged.
void runGuarded(const std::function<void()>& fn);

} // namespace hlod::cad
