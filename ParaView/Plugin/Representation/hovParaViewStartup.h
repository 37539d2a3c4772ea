// The plugin's one-time set-up inside a ParaView process (every rank).
#ifndef hovParaViewStartup_h
#define hovParaViewStartup_h

namespace hov
{
/**
 * Runs once per process (later calls return at once):
 *  - vtkSMPTools: ParaView 5.11's VTK defaults to the Sequential backend, on
 *    which the mapper's CPU paths use one thread. Unless the user chose a
 *    backend (VTK_SMP_BACKEND_IN_USE), switch to STDThread (threads:
 *    VTK_SMP_MAX_THREADS, else all cores).
 *  - Version: the plugin is compiled against one ParaView release; loaded
 *    into another one whose libraries still resolve (same soname, other
 *    patch level or build) it prints a clear error naming both versions.
 * Returns false if the version check failed.
 */
bool ParaViewStartup();
}

#endif
