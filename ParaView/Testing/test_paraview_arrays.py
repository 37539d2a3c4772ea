"""hov.ParaView.Arrays: what "Accurate Volume" takes from ParaView's display: the colouring
array (switched), the separate opacity array, the selected blocks, the LOD surface (pvbatch,
one rank, CPU accurate, the bracket). The plugin's float images (.vti) are compared with each
other.

1. Colour maps kept per array. von_mises with ParaView's default map (discretized: the
   representation renders a continuous copy of it), then displacement_magnitude with its own
   map, then von_mises again without touching its map, as a user switching back does. The
   third image must equal the first. (The copy used to be refreshed only when the map's
   modification time was newer than the last copy's, so switching back kept the second
   array's map.) The second image must differ from the first, so that the check can fail.
2. A separate opacity array with ParaView's Magnitude. Colour by von_mises; the extinction
   from the 3-component displacement with VolumeOpacityComponent = 3 (ParaView's encoding of
   Magnitude), from the stored one-component displacement_magnitude, and from displacement's
   z component (2). The first two must agree to 1e-4 (the stored magnitude is rounded to
   float); the z component must differ. (Magnitude used to reach the mapper as component 3,
   clamped to the last component: the z image.)
3. Blocks of a multiblock input selected with ParaView's BlockSelectors ("Blocks"): block A
   alone must equal the dataset alone, both must add up, none must draw nothing with a
   warning (the selection used to be ignored: every block was drawn). Block A of a
   partitioned dataset collection is the dataset alone too; a partitioned dataset draws
   both partitions (selectors do not address partitions); one grid of both with block B's
   cells marked as ghosts draws block A alone (ghost cells were drawn).
4. 'Map Scalars' off, then 'Multi Components Mapping' on, on one display: a warning for each.
5. The LOD surface ParaView draws during interaction above the view's LOD threshold (set to
   0 here): coloured by von_mises through the colour map, not the plain white surface it
   used to be; also by an 8-bit array (von_mises scaled to 0-255), which VTK's default
   colour mode would show as grey levels.
"""
import os

import numpy as np

import hov_pv_testing as hpt

SIZE = (120, 120)
DISPLACEMENT_MAX = 0.23003099314586073
BLOCK_SHIFT = [130.0, 0.0, 0.0]  # block B beside block A (the bracket is 100 wide in x)


def displacement_nodes():
    """A colour map and an opacity function over displacement's range [0, 0.23]."""
    hi = DISPLACEMENT_MAX
    color = [[f * hi, r, g, b] for f, r, g, b in hpt.COLOR_NODES]
    opacity = [[f * hi, a] for f, a in hpt.OPACITY_NODES]
    return color, opacity


def byte_lod_case(args, plain):
    """The LOD frame coloured by an 8-bit array (von_mises scaled to 0-255 by ParaView's
    Calculator): mapped through the colour map, not taken as grey levels."""
    lo, hi = hpt.DATASETS["bracket"]["range"]
    case = hpt.make_case(args, "bracket", 0, tag="lod_bytes", interactive_lod=True,
                         properties=dict(plain, MultiComponentsMapping=0))
    case.update(array="von_mises_bytes", calculator={
        "function": "255 * (von_mises - %.17g) / %.17g" % (lo, hi - lo),
        "type": "Unsigned Char"},
        color=[[f * 255.0, r, g, b] for f, r, g, b in hpt.COLOR_NODES],
        opacity=[[f * 255.0, a] for f, a in hpt.OPACITY_NODES])
    return case


def block_cases(args):
    """The bracket alone and as block A of a multiblock whose block B is the bracket moved
    past it, with block selections; one camera framing both."""
    camera = hpt.camera_for("bracket", zoom=0.5)
    for key in ("position", "focal_point"):
        camera[key] = [camera[key][0] + BLOCK_SHIFT[0] / 2] + camera[key][1:]
    cases = [hpt.make_case(args, "bracket", 0, tag="single", camera=camera,
                           properties={"VolumeUseSeparateOpacityArray": 0})]
    multiblock, partitioned = "vtkMultiBlockDataSet", "vtkPartitionedDataSet"
    collection = "vtkPartitionedDataSetCollection"
    for tag, group_type, selectors in (
            ("blocks_all", multiblock, ["/"]), ("blocks_a", multiblock, ["/Root/BlockA"]),
            ("blocks_b", multiblock, ["/Root/BlockB"]), ("blocks_none", multiblock, []),
            ("collection_a", collection, ["/Root/BlockA"]),
            ("partitioned_all", partitioned, ["/"]), ("ghosts_b", "ghosts", ["/"])):
        cases.append(hpt.make_case(args, "bracket", 0, tag=tag, camera=camera,
                                   blocks=BLOCK_SHIFT, group_type=group_type,
                                   properties={"BlockSelectors": selectors}))
    return cases


def check_blocks(failures, images, screenshots, messages):
    """Block A alone is the bracket alone; B is elsewhere; both are more than either;
    no block selected draws nothing and says so."""
    def max_diff(a, b):
        return float(np.abs(images[a] - images[b]).max())
    for name, same, what in (
            ("blocks_a", "single", "block A selected: the bracket alone"),
            ("collection_a", "single", "partitioned collection, block A: the bracket alone"),
            ("partitioned_all", "blocks_all", "partitioned dataset: both partitions"),
            ("ghosts_b", "single", "one grid, B's cells ghosts: the bracket alone")):
        hpt.check(failures, max_diff(name, same) <= 1e-6,
                  "%s (max %.2e <= 1e-6)" % (what, max_diff(name, same)))
    for a, b in (("blocks_b", "single"), ("blocks_all", "blocks_a"), ("blocks_all", "blocks_b")):
        hpt.check(failures, max_diff(a, b) > 1e-2, "%s differs from %s (max %.2f)"
                  % (a, b, max_diff(a, b)))
    drawn = {name: float(images[name][..., 3].sum()) for name in ("blocks_all", "blocks_a",
                                                                  "blocks_b")}
    hpt.check(failures, abs(drawn["blocks_all"] - drawn["blocks_a"] - drawn["blocks_b"])
              < 0.02 * drawn["blocks_all"],
              "both blocks: their opacities add up (%.1f vs %.1f + %.1f; they do not overlap)"
              % (drawn["blocks_all"], drawn["blocks_a"], drawn["blocks_b"]))
    hpt.check(failures, float(screenshots["blocks_none"].max()) == 0.0 and
              float(screenshots["blocks_all"].max()) > 0.0 and
              "no block is selected" in messages.get("blocks_none", ""),
              "no block selected: a black screenshot and a warning")


def check_lod(failures, result):
    """The interactive LOD frame is a surface coloured through the case's colour map: each
    pixel's colour, scaled to its largest channel (shading scales it), lies near a colour of
    the map, so scaled."""
    lod = hpt.read_png_rgb(result["lod_png"]) / 255.0
    still = hpt.read_png_rgb(result["png"]) / 255.0
    drawn = lod.max(axis=2) > 10.0 / 255.0
    name = result["name"]
    hpt.check(failures, int(drawn.sum()) > 1000, "%s: LOD frame, %d pixels drawn"
              % (name, int(drawn.sum())))
    hpt.check(failures, float(np.abs(lod - still).mean()) > 5.0 / 255.0,
              "%s: LOD frame differs from the still volume frame (mean %.1f/255)"
              % (name, 255.0 * float(np.abs(lod - still).mean())))
    nodes = np.array(hpt.COLOR_NODES)
    t = np.linspace(0.0, 1.0, 256)
    cmap = np.stack([np.interp(t, nodes[:, 0], nodes[:, k]) for k in (1, 2, 3)], axis=1)
    cmap /= cmap.max(axis=1, keepdims=True)
    pixels = lod[drawn]
    pixels = pixels / np.maximum(pixels.max(axis=1, keepdims=True), 1e-6)
    distance = np.sqrt(((pixels[:, None, :] - cmap[None]) ** 2).sum(axis=2)).min(axis=1)
    on_map = float((distance < 0.1).mean()) if pixels.size else 0.0
    hpt.check(failures, on_map > 0.8,
              "%s: LOD frame coloured through the colour map: %.1f%% of its pixels (> 80%%)"
              % (name, 100.0 * on_map))
    blue = float((pixels.argmax(axis=1) == 2).mean()) if pixels.size else 0.0
    hpt.check(failures, blue > 0.2,
              "%s: LOD frame shows the map's low (blue) end: %.1f%% of its pixels (> 20%%)"
              % (name, 100.0 * blue))


def main():
    args = hpt.parse_args()
    failures = []
    color, opacity = displacement_nodes()
    first = hpt.make_case(args, "bracket", 0, tag="von_mises_first", paraview_colormap=True)
    other = hpt.make_case(args, "bracket", 0, tag="displacement_magnitude",
                          paraview_colormap=True)
    other.update(array="displacement_magnitude", color=color, opacity=opacity)
    again = hpt.make_case(args, "bracket", 0, tag="von_mises_again",
                          keep_transfer_functions=True)
    cases = [first, other, again]
    # Separate opacity array: the colour map over von_mises, the opacity function over
    # displacement's range (whichever function ParaView passes, it is the same in all three).
    for tag, array, component in (("opacity_magnitude", "displacement", 3),
                                  ("opacity_stored_magnitude", "displacement_magnitude", 0),
                                  ("opacity_z", "displacement", 2)):
        case = hpt.make_case(args, "bracket", 0, tag=tag, properties={
            "VolumeUseSeparateOpacityArray": 1,
            "VolumeOpacityArrayName": ["POINTS", array],
            "VolumeOpacityComponent": component})
        case["opacity"] = opacity
        cases.append(case)
    # The bracket's display keeps the properties set above: the separate opacity array off.
    plain = {"VolumeUseSeparateOpacityArray": 0}
    cases.append(hpt.make_case(args, "bracket", 0, tag="lod", interactive_lod=True,
                               properties=plain))
    cases += block_cases(args)
    # Two ignored settings on one display: each warned once, the second after the first.
    cases.append(hpt.make_case(args, "bracket", 0, tag="map_scalars_off", properties=dict(
        plain, MapScalars=0)))
    cases.append(hpt.make_case(args, "bracket", 0, tag="multi_components", properties=dict(
        plain, MapScalars=1, MultiComponentsMapping=1)))
    cases.append(byte_lod_case(args, plain))
    out = os.path.join(args.temp, "paraview_arrays")
    results, stderr = hpt.run_pvbatch(args, cases, out, SIZE)
    hpt.check(failures, not hpt.has_errors(stderr),
              "pvbatch ran without errors (%.1f s)" % results["seconds"])
    # No block selected: ParaView does not call the mapper, so no float image (the
    # screenshot is checked instead).
    images = {res["name"]: hpt.read_vti_rgba(res["vti"]) for res in results["cases"]
              if res["name"] != "blocks_none"}
    screenshots = {res["name"]: hpt.read_png_rgb(res["png"]) for res in results["cases"]}
    for name in ("lod", "lod_bytes"):
        check_lod(failures, next(res for res in results["cases"] if res["name"] == name))
    for name, img in images.items():
        hpt.check(failures, int((img[..., 3] > 1e-3).sum()) > 1000,
                  "%s: the image is not empty" % name)

    def max_diff(a, b):
        return float(np.abs(images[a] - images[b]).max())

    # (what, image a, image b, bound, whether they must agree within it or differ beyond it)
    comparisons = [
        ("colour map switched back: von_mises again vs first", "von_mises_first",
         "von_mises_again", 1e-7, True),
        ("the other array's image vs von_mises'", "von_mises_first", "displacement_magnitude",
         1e-2, False),
        ("separate opacity, Magnitude vs the stored magnitude", "opacity_magnitude",
         "opacity_stored_magnitude", 1e-4, True),
        ("separate opacity, Magnitude vs the z component", "opacity_magnitude", "opacity_z",
         1e-2, False),
    ]
    for what, a, b, bound, agree in comparisons:
        d = max_diff(a, b)
        hpt.check(failures, d <= bound if agree else d > bound,
                  "%s: max %.2e (%s %.0e)" % (what, d, "<=" if agree else ">", bound))
    messages = hpt.messages_by_case(stderr)
    check_blocks(failures, images, screenshots, messages)
    for name, setting in (("map_scalars_off", "'Map Scalars' off"),
                          ("multi_components", "'Multi Components Mapping'")):
        hpt.check(failures, setting + " is ignored" in messages[name],
                  "%s: a warning that it is ignored" % setting)
    hpt.finish(failures)


if __name__ == "__main__":
    main()
