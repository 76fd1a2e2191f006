import numpy as np
import cv2
from hw1 import render_img

data = np.load("hw1.npy", allow_pickle=True).tolist()
img = render_img(data["faces"], data["vertices"], data["vcolors"], data["depth"], "f")
img *= 255
img = img.astype(np.uint8)
img = cv2.cvtColor(img, cv2.COLOR_RGB2BGR)
cv2.imwrite("flat.jpg", img)
cv2.imshow("flat", img)
cv2.waitKey(0)
