#include "hovParaViewStartup.h"

#include "vtkLogger.h"         // messages
#include "vtkOutputWindow.h"   // the version error where ParaView shows errors
#include "vtkPVVersion.h"      // the version the plugin was compiled against
#include "vtkSMPTools.h"       // the SMP backend
#include "vtkSMProxyManager.h" // the version the plugin runs in

#include <cstdlib> // std::getenv
#include <cstring> // std::strcmp
#include <mutex>   // std::call_once
#include <sstream> // messages

namespace hov
{
namespace
{
bool CheckVersion()
{
  const int major = vtkSMProxyManager::GetVersionMajor();
  const int minor = vtkSMProxyManager::GetVersionMinor();
  const int patch = vtkSMProxyManager::GetVersionPatch();
  if (major == PARAVIEW_VERSION_MAJOR && minor == PARAVIEW_VERSION_MINOR &&
    patch == PARAVIEW_VERSION_PATCH)
  {
    return true;
  }
  std::ostringstream message;
  message << "HighOrderVolume plugin: built for ParaView " << PARAVIEW_VERSION_FULL
          << " but loaded into ParaView " << major << "." << minor << "." << patch
          << ". Rebuild the plugin against this ParaView (ParaView/ in the HighOrderVolume "
             "sources); it may misbehave until then.\n";
  vtkOutputWindow::GetInstance()->DisplayErrorText(message.str().c_str());
  return false;
}

void UseThreadedBackend()
{
  if (std::getenv("VTK_SMP_BACKEND_IN_USE") != nullptr)
  {
    return; // the user's choice
  }
  const char* backend = vtkSMPTools::GetBackend();
  if (backend && std::strcmp(backend, "Sequential") == 0 && vtkSMPTools::SetBackend("STDThread"))
  {
    // STDThread's default is all cores; VTK_SMP_MAX_THREADS limits it.
    const char* maxThreads = std::getenv("VTK_SMP_MAX_THREADS");
    vtkSMPTools::Initialize(maxThreads ? std::atoi(maxThreads) : 0);
    vtkVLogF(vtkLogger::VERBOSITY_INFO,
      "HighOrderVolume plugin: vtkSMPTools backend Sequential -> STDThread, %d threads",
      vtkSMPTools::GetEstimatedNumberOfThreads());
  }
}
}

bool ParaViewStartup()
{
  static std::once_flag once;
  static bool versionOk = true;
  std::call_once(once, [] {
    versionOk = CheckVersion();
    UseThreadedBackend();
  });
  return versionOk;
}
}
