"""Kinetic energy against its initial value in an explicit run's history (check_energy_growth.py CSV MODE):
MODE stable: ALLKE never exceeds the initial kinetic energy (nothing feeds the system; 1e-9 relative);
MODE unstable: ALLKE grows past 10x the initial kinetic energy somewhere (the run is unstable)."""
import csv
import sys

rows = list(csv.DictReader(open(sys.argv[1])))
ke = [float(r["ALLKE"]) for r in rows]
ke0 = float(sys.argv[3]) if len(sys.argv) > 3 else 2.5e-7
growth = max(ke) / ke0
print("rows %d, largest ALLKE %.6g, initial %.6g: growth %.4g" % (len(rows), max(ke), ke0, growth))
if sys.argv[2] == "stable":
    ok = growth <= 1 + 1e-9
    print("largest ALLKE / initial kinetic energy: %.6g (expected at most 1) %s" % (growth, "PASS" if ok else "FAIL"))
else:
    ok = growth > 10
    print("largest ALLKE / initial kinetic energy: %.6g (expected above 10: unstable) %s" % (growth, "PASS" if ok else "FAIL"))
sys.exit(0 if ok else 1)
