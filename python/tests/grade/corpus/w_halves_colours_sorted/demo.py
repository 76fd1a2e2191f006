import numpy as np
import matplotlib.pyplot as plt
from hw1 import render_img

data = np.load("hw1.npy", allow_pickle=True).item()
fig, ax = plt.subplots(1, 2)
for a, s in zip(ax, "fg"):
    a.imshow(render_img(data["faces"], data["vertices"], data["vcolors"], data["depth"], s))
    a.set_title("flat" if s == "f" else "gouraud")
plt.savefig("results.png")
