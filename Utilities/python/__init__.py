"""highordervolume: accurate volume rendering of unstructured finite-element data.

Import this package after (or instead of) the VTK modules you use; it brings
vtkHighOrderVolumeMapper and vtkHighOrderTransferFunction:

    from highordervolume import vtkHighOrderVolumeMapper
"""
# The OpenGL2 factory overrides must be loaded for rendering to work.
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401
import vtkmodules.vtkRenderingVolumeOpenGL2  # noqa: F401

from .vtkRenderingHighOrderVolume import *  # noqa: F401,F403
