"""hov.ParaView.MPI<N>: "mpiexec -np N pvbatch" with ParaView's kd-tree redistribution and
IceT ordered compositing renders the bracket, the zoo, and block B of a multiblock of the
bracket and a moved copy (ParaView's block selection on every rank; CPU accurate); each composited
screenshot must equal the 1-rank screenshot of the same camera within 3/255 (max over
pixels and channels). IceT reads each rank's layer back as 8-bit RGBA before compositing,
so a few /255 are expected; 3/255 is the acceptance bound.

Also checked: rank 0's mapper got only a part of the mesh (the redistribution happened;
its piece keeps native cells), every other rank wrote its own float layer, and no rank
printed an error. One thread per rank (VTK_SMP_MAX_THREADS=1), --oversubscribe when there
are more ranks than cores.
"""
import os

import numpy as np

import hov_pv_testing as hpt

SIZE = (200, 200)


def extra(parser):
    parser.add_argument("--ranks", type=int, required=True)


def main():
    args = hpt.parse_args(extra)
    failures = []
    cases = [hpt.make_case(args, name, 0) for name in ("bracket", "zoo")]
    # A multiblock of the bracket (block A) and a moved copy (block B), block B selected:
    # each rank draws the selected block of its own piece.
    camera = hpt.camera_for("bracket")
    for key in ("position", "focal_point"):
        camera[key] = [camera[key][0] + 130.0] + camera[key][1:]
    cases.append(hpt.make_case(args, "bracket", 0, tag="bracket_block_b", camera=camera,
                               blocks=[130.0, 0.0, 0.0],
                               properties={"BlockSelectors": ["/Root/BlockB"]}))
    # The 1-rank reference of the same cases (its own run: the same script, one rank).
    ref_out = os.path.join(args.temp, "paraview_mpi_ref_%d" % args.ranks)
    ref, _ = hpt.run_pvbatch(args, cases, ref_out, SIZE)
    out = os.path.join(args.temp, "paraview_mpi_%d" % args.ranks)
    res, stderr = hpt.run_pvbatch(args, cases, out, SIZE, ranks=args.ranks,
                                  oversubscribe=args.ranks > os.cpu_count(), threads=1)
    hpt.check(failures, not hpt.has_errors(stderr),
              "%d ranks: no errors in the output (%.1f s)" % (args.ranks, res["seconds"]))
    for case, one, many in zip(cases, ref["cases"], res["cases"]):
        name = case["name"]
        a = hpt.read_png_rgb(one["png"])
        b = hpt.read_png_rgb(many["png"])
        diff = np.abs(a - b)
        dmax = float(diff.max())
        hpt.check(failures, dmax <= 3.0,
                  "%s: %d ranks vs 1 rank: max %.0f/255 (<= 3), mean %.4f/255, %d pixels differ"
                  % (name, args.ranks, dmax, float(diff.mean()), int((diff.max(axis=2) > 0).sum())))
        hpt.check(failures, float(a.max()) > 50, "%s: the 1-rank image is not empty" % name)
        info = many["info"]
        total = hpt.DATASETS[case["dataset"]]["cells"]
        # The zoo's piece keeps several cell types: native cells, not tetrahedra.
        min_types = 2 if case["dataset"] == "zoo" else 1
        hpt.check(failures, 0 < info["PieceCells"] < total and info["PieceCellTypes"] >= min_types,
                  "%s: rank 0 renders %d of %d cells (%d types, >= %d): the mesh was "
                  "redistributed, cells native" % (
                      name, info["PieceCells"], total, info["PieceCellTypes"], min_types))
        layers = [f for f in os.listdir(out) if f.startswith(name + "_rank")]
        hpt.check(failures, len(layers) == args.ranks - 1,
                  "%s: every other rank wrote its own float layer (%d)" % (name, len(layers)))
    # Rank 0's share of the selected block B is about its share of the bracket alone (both
    # blocks would double it).
    pieces = {c["name"]: r["info"]["PieceCells"] for c, r in zip(cases, res["cases"])}
    hpt.check(failures, pieces["bracket_block_b"] < 1.5 * pieces["bracket_cpu"],
              "block B selected: rank 0 holds %d cells, about its %d of the bracket alone"
              % (pieces["bracket_block_b"], pieces["bracket_cpu"]))
    hpt.finish(failures)


if __name__ == "__main__":
    main()
