import numpy as np
import matplotlib.pyplot as plt
from triangle_filling import render

data = np.load("hw1.npy", allow_pickle=True).item()
img = render(data["vertices"], data["faces"], data["vcolors"], data["depth"], "flat")
plt.imsave("flat.png", img)
