import numpy as np
from f_shading import f_shading
from g_shading import g_shading


def render_img(faces, vertices, vcolors, depth, shading):
    img = np.ones((512, 512, 3))
    depths = [(depth[f[0]] + depth[f[1]] + depth[f[2]]) / 3 for f in faces]
    order = sorted(range(len(faces)), key=lambda i: -depths[i])
    for i in order:
        tri = [vertices[k] for k in faces[i]]
        cols = [vcolors[k] for k in faces[i]]
        if shading == "f":
            f_shading(img, tri, cols)
        elif shading == "g":
            g_shading(img, tri, cols)
    return img
