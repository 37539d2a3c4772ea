# hov_paraview_shim(<original config dir> <extracted python3-paraview root> <shim dir>)
#
# Debian's paraview-dev ships ParaView's CMake package, but that package
# also names files only python3-paraview installs (ParaView's and its VTK's
# Python modules, pvpython, the wrapping hierarchy files). python3-paraview
# cannot be installed beside python3-vtk9 (it Conflicts with it), so the set-up
# script extracts it into a folder instead (Utilities/setup-debian.sh).
#
# This function writes a copy of ParaView's CMake package into <shim dir> in
# which:
#  - every install prefix is still the real one (/usr): each file's prefix is
#    computed from the ORIGINAL file's location, so libraries, headers and
#    tools are Debian's own;
#  - only the Python modules, pvpython and the hierarchy files point into the
#    extracted python3-paraview tree.
# Nothing outside the build tree is touched and no root is needed.
function (hov_paraview_shim original python_root shim)
  file(GLOB_RECURSE files RELATIVE "${original}" "${original}/*")
  set(py_dist "${python_root}/usr/lib/python3/dist-packages")
  set(py_hierarchy "${python_root}/usr/lib/x86_64-linux-gnu/vtk/hierarchy/ParaView")
  foreach (rel IN LISTS files)
    set(src "${original}/${rel}")
    set(dst "${shim}/${rel}")
    get_filename_component(rel_dir "${rel}" DIRECTORY)
    if (NOT rel MATCHES "\\.cmake$")
      configure_file("${src}" "${dst}" COPYONLY)
      continue ()
    endif ()
    file(READ "${src}" text)
    # Prefixes from the original location of the file.
    string(REPLACE
      "get_filename_component(_IMPORT_PREFIX \"\${CMAKE_CURRENT_LIST_FILE}\" PATH)"
      "get_filename_component(_IMPORT_PREFIX \"${src}\" PATH)"
      text "${text}")
    string(REPLACE
      "set(_vtk_module_import_prefix \"\${CMAKE_CURRENT_LIST_DIR}\")"
      "set(_vtk_module_import_prefix \"${original}/${rel_dir}\")"
      text "${text}")
    string(REPLACE
      "get_filename_component(PACKAGE_PREFIX_DIR \"\${CMAKE_CURRENT_LIST_DIR}/"
      "get_filename_component(PACKAGE_PREFIX_DIR \"${original}/${rel_dir}/"
      text "${text}")
    # The python3-paraview files from the extracted tree.
    string(REPLACE "\${_IMPORT_PREFIX}/lib/python3/dist-packages/" "${py_dist}/" text "${text}")
    string(REPLACE "\${_IMPORT_PREFIX}/bin/pvpython" "${python_root}/usr/bin/pvpython"
      text "${text}")
    string(REPLACE
      "\${_vtk_module_import_prefix}/lib/x86_64-linux-gnu/vtk/hierarchy/ParaView/"
      "${py_hierarchy}/" text "${text}")
    # configure_file only rewrites a file whose content changed (no rebuilds).
    file(WRITE "${dst}.tmp" "${text}")
    configure_file("${dst}.tmp" "${dst}" COPYONLY)
    file(REMOVE "${dst}.tmp")
  endforeach ()
endfunction ()
