import numpy as np
import cv2
from hw1 import render_img

if __name__ == "__main__":
    data = np.load("hw1.npy", allow_pickle=True).item()
    img = render_img(data["faces"], data["vertices"], data["vcolors"], data["depth"], "g")
    cv2.imwrite("gouraud.png", (img[:, :, ::-1] * 255).astype(np.uint8))
