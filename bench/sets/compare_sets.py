"""Compare two dumps of bench/sets/hermite_sets.c (an old build's, a new one's): each old
solution is matched to the nearest new one of the same problem (greedily, nearest pairs
first) by the largest difference of L/d, sigma d^2, kappa0 d, kappa1 d (relative above 1),
the same solution where that is below --same. Prints the problems that lost or gained a
solution or changed status, and one summary line; exits 1 when a solution was lost.

    python3 compare_sets.py old.txt new.txt [--same 1e-6]
"""
import argparse
import sys


def read(path):
    """{(set, index): (rc, unrepresentable, [solution tuples])}"""
    problems, cur = {}, None
    with open(path) as f:
        for line in f:
            w = line.split()
            if w[0] == "P":
                cur = problems[(int(w[1]), int(w[2]))] = (int(w[3]), int(w[5]), [])
            else:
                cur[2].append(tuple(float(v) for v in w[1:6]) + (int(w[6]),))
    return problems


def distance(a, b):
    return max(abs(x - y) / max(1.0, abs(x)) for x, y in zip(a[:4], b[:4]))


def match(old, new):
    """pairs (i, j, distance) nearest first, each solution in one pair at most"""
    pairs = sorted((distance(a, b), i, j) for i, a in enumerate(old) for j, b in enumerate(new))
    used_i, used_j, out = set(), set(), []
    for dist, i, j in pairs:
        if i not in used_i and j not in used_j:
            used_i.add(i)
            used_j.add(j)
            out.append((i, j, dist))
    return out


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("old")
    ap.add_argument("new")
    ap.add_argument("--same", type=float, default=1e-6)
    a = ap.parse_args()
    old, new = read(a.old), read(a.new)
    if old.keys() != new.keys():
        sys.exit("compare_sets: the dumps hold different problems")
    lost = gained = solutions = status = 0
    deviation = 0.0
    for key in sorted(old):
        (rc0, u0, s0), (rc1, u1, s1) = old[key], new[key]
        solutions += len(s0)
        pairs = [p for p in match(s0, s1) if p[2] <= a.same]
        l, g = len(s0) - len(pairs), len(s1) - len(pairs)
        deviation = max([deviation] + [p[2] for p in pairs])
        if rc0 != rc1 or u0 != u1:
            status += 1
            print(f"set {key[0]} problem {key[1]}: status {rc0} -> {rc1}, unrepresentable {u0} -> {u1}")
        if l or g:
            print(f"set {key[0]} problem {key[1]}: {len(s0)} -> {len(s1)} solutions, lost {l}, gained {g}")
            lost += l
            gained += g
    print(f"hermite-sets: {len(old)} problems, {solutions} old solutions: lost {lost}, gained {gained}, "
          f"status changed {status}, largest deviation of the kept {deviation:.3g}")
    return 1 if lost else 0


if __name__ == "__main__":
    sys.exit(main())
