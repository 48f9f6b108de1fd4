"""Shapes of a world file (spott_worlds) shared by the scorers of recorded runs."""


def inside(p, polygon):
    """Whether point p lies inside the polygon (even-odd rule)."""
    x, y = p
    hit = False
    for (x1, y1), (x2, y2) in zip(polygon, polygon[1:] + polygon[:1]):
        if (y1 > y) != (y2 > y) and x < x1 + (y - y1) * (x2 - x1) / (y2 - y1):
            hit = not hit
    return hit
