"""highordervolume: accurate volume rendering of unstructured finite-element data.

Import this package after (or instead of) the VTK modules you use; it brings
vtkHighOrderVolumeMapper and vtkHighOrderTransferFunction:

    from highordervolume import vtkHighOrderVolumeMapper

Command-line tools (modules imported on demand, also installed as bin/hov-compare and
bin/hov-convergence): `python3 -m highordervolume.compare` (our render modes against VTK's
volume mappers: images, montage, error/time/memory table) and `python3 -m
highordervolume.convergence` (error against cost for one knob, observed order).
"""
# The OpenGL2 factory overrides must be loaded for rendering to work.
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401
import vtkmodules.vtkRenderingVolumeOpenGL2  # noqa: F401

from .vtkRenderingHighOrderVolume import *  # noqa: F401,F403
