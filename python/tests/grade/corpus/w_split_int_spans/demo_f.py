import time
import numpy as np
import matplotlib.pyplot as plt
from render_img import render_img

if __name__ == "__main__":
    data = np.load("hw1.npy", allow_pickle=True).item()
    start = time.time()
    img = render_img(data["faces"], data["vertices"], data["vcolors"], data["depth"], "f")
    print("flat shading took", time.time() - start, "s")
    plt.imsave("flat.png", img)
