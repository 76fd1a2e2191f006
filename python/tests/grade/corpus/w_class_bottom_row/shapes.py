import math


class Edge:
    def __init__(self, p, q, cp, cq):
        # p is the upper end point (smaller y)
        if p[1] > q[1]:
            p, q, cp, cq = q, p, cq, cp
        self.p, self.q = p, q
        self.cp, self.cq = cp, cq
        self.horizontal = p[1] == q[1]

    def covers(self, y):
        return not self.horizontal and self.p[1] <= y < self.q[1]

    def x_at(self, y):
        return self.p[0] + (self.q[0] - self.p[0]) * (y - self.p[1]) / (self.q[1] - self.p[1])


class Triangle:
    def __init__(self, vertices, colors):
        self.v = [(float(a), float(b)) for a, b in vertices]
        self.c = colors
        self.edges = [Edge(self.v[i], self.v[(i + 1) % 3], colors[i], colors[(i + 1) % 3])
                      for i in range(3)]

    def degenerate(self):
        (x0, y0), (x1, y1), (x2, y2) = self.v
        return (x1 - x0) * (y2 - y0) - (y1 - y0) * (x2 - x0) == 0

    def scanlines(self):
        """yields (y, left edge, x_left, right edge, x_right) for every scanline of the triangle"""
        ys = [p[1] for p in self.v]
        for y in range(math.ceil(min(ys)), math.ceil(max(ys)) - 1):
            act = [(e.x_at(y), e) for e in self.edges if e.covers(y)]
            if len(act) != 2:
                continue
            act.sort(key=lambda t: t[0])
            yield y, act[0][1], act[0][0], act[1][1], act[1][0]
