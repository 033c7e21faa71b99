"""Run inside FreeCAD (freecadcmd bench/freecad_approx.py): Part.BSplineCurve().approximate
on the point sets of the job file named by $ELASTICA_FC_JOB, results (poles, knots,
mults, degree, time) written to the job's "output" file. freecadcmd exits 0 even when a
script raises, so the caller checks that the output exists and says "ok"."""
import json
import os
import time
import traceback

import FreeCAD
import Part

job = json.load(open(os.environ["ELASTICA_FC_JOB"]))
results = []
try:
    for case in job["cases"]:
        pts = [FreeCAD.Vector(x, y, 0.0) for x, y in case["points"]]
        t0 = time.perf_counter()
        res = {"id": case["id"]}
        try:
            c = Part.BSplineCurve()
            c.approximate(Points=pts, DegMin=case["degmin"], DegMax=case["degmax"],
                          Tolerance=case["tol"], Continuity=case.get("continuity", "C2"),
                          ParamType="ChordLength")
            res.update(time_s=time.perf_counter() - t0, degree=c.Degree,
                       poles=[[p.x, p.y] for p in c.getPoles()], knots=list(c.getKnots()),
                       mults=list(c.getMultiplicities()), rational=c.isRational())
        except Exception as exc:  # a failed approximation is a result too
            res["error"] = repr(exc)
        results.append(res)
    status = "ok"
except Exception:
    status = traceback.format_exc()
json.dump({"status": status, "results": results}, open(job["output"], "w"))
