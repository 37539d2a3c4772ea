"""hov.ParaView.GUI: the ParaView GUI (paraview, Qt, under Xvfb) runs gui_script.py: the
plugin loads, "Accurate Volume" is among the zoo's representations (the representation
menu's list), its native cells reach the mapper (68,714 of 4 types) in the CPU and the
OpenGL projection modes inside the GUI's render widget, and the screenshot is not empty.
"""
import json
import os
import subprocess

import hov_pv_testing as hpt


def main():
    args = hpt.parse_args()
    failures = []
    out = os.path.join(args.temp, "paraview_gui")
    os.makedirs(out, exist_ok=True)
    env = hpt.pv_env(args)
    env.update(HOV_GUI_PLUGIN_DIR=os.path.dirname(args.plugin),
               HOV_GUI_DATA=os.path.join(args.data, "zoo_mixed_ccx.vtu"),
               HOV_GUI_PNG=os.path.join(out, "gui_zoo.png"),
               HOV_GUI_RESULT=os.path.join(out, "gui.json"))
    for f in (env["HOV_GUI_PNG"], env["HOV_GUI_RESULT"]):
        if os.path.exists(f):
            os.remove(f)
    proc = subprocess.run(["paraview", "--dr", "--script=" + os.path.join(hpt.HERE, "gui_script.py")],
                          env=env, capture_output=True, text=True, timeout=600)
    hpt.check(failures, os.path.exists(env["HOV_GUI_RESULT"]),
              "the GUI ran the script (exit %d)" % proc.returncode)
    if failures:
        print(proc.stdout[-2000:] + proc.stderr[-2000:])
        hpt.finish(failures)
    with open(env["HOV_GUI_RESULT"]) as f:
        result = json.load(f)
    hpt.check(failures, "error" not in result, "no Python error: %s" % result.get("error", ""))
    hpt.check(failures, "Accurate Volume" in result.get("available", []),
              "'Accurate Volume' in the representation list %s" % result.get("available"))
    for mode in ("CPU accurate", "OpenGL projection"):
        info = result.get(mode, {})
        hpt.check(failures, info.get("PieceCells") == 68714 and info.get("PieceCellTypes") == 4 and
                  info.get("RenderedCells") == 68714 and info.get("RenderCalls", 0) > 0,
                  "%s in the GUI: %s" % (mode, info))
    img = hpt.read_png_rgb(env["HOV_GUI_PNG"])
    hpt.check(failures, float(img.std()) > 5.0, "the GUI screenshot is not blank (std %.1f)" % img.std())
    hpt.finish(failures)


if __name__ == "__main__":
    main()
