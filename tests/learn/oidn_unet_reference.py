"""Open Image Denoise's U-Net written from its published design (Afra et al.; the sizes in
libmatlearn's denoising_unet.h), the reference for tests/learn/learned_denoiser_test.cpp.

Usage: oidn_unet_reference.py OUT_DIR
Writes into OUT_DIR:
  weights.pth  the state dict, torch's default initialisation with seed 0;
  io.pt        {"input": 1x9x48x32, "output": 1x3x48x32} in eval mode.
"""
import sys

import torch
from torch import nn
import torch.nn.functional as F


def conv(c_in, c_out):
    return nn.Conv2d(c_in, c_out, 3, padding=1)


class OidnUNet(nn.Module):
    def __init__(self, c_in=9, c_out=3):
        super().__init__()
        self.enc_conv0, self.enc_conv1 = conv(c_in, 32), conv(32, 32)
        self.enc_conv2, self.enc_conv3, self.enc_conv4 = conv(32, 48), conv(48, 64), conv(64, 80)
        self.enc_conv5a, self.enc_conv5b = conv(80, 96), conv(96, 96)
        self.dec_conv4a, self.dec_conv4b = conv(96 + 64, 112), conv(112, 112)
        self.dec_conv3a, self.dec_conv3b = conv(112 + 48, 96), conv(96, 96)
        self.dec_conv2a, self.dec_conv2b = conv(96 + 32, 64), conv(64, 64)
        self.dec_conv1a, self.dec_conv1b = conv(64 + c_in, 64), conv(64, 32)
        self.dec_conv0 = conv(32, c_out)

    def forward(self, x):
        up = lambda t: F.interpolate(t, scale_factor=2, mode="nearest")
        pool = lambda t: F.max_pool2d(t, 2, 2)
        inp = x
        x = F.relu(self.enc_conv0(x))
        pool1 = pool(F.relu(self.enc_conv1(x)))
        pool2 = pool(F.relu(self.enc_conv2(pool1)))
        pool3 = pool(F.relu(self.enc_conv3(pool2)))
        x = pool(F.relu(self.enc_conv4(pool3)))
        x = F.relu(self.enc_conv5b(F.relu(self.enc_conv5a(x))))
        x = F.relu(self.dec_conv4b(F.relu(self.dec_conv4a(torch.cat([up(x), pool3], 1)))))
        x = F.relu(self.dec_conv3b(F.relu(self.dec_conv3a(torch.cat([up(x), pool2], 1)))))
        x = F.relu(self.dec_conv2b(F.relu(self.dec_conv2a(torch.cat([up(x), pool1], 1)))))
        x = F.relu(self.dec_conv1b(F.relu(self.dec_conv1a(torch.cat([up(x), inp], 1)))))
        return self.dec_conv0(x)


def main(out_dir):
    torch.manual_seed(0)
    model = OidnUNet().eval()
    x = torch.rand(1, 9, 48, 32)
    with torch.no_grad():
        y = model(x)
    torch.save(dict(model.state_dict()), f"{out_dir}/weights.pth")
    torch.save({"input": x, "output": y}, f"{out_dir}/io.pt")
    print(sum(p.numel() for p in model.parameters()))


if __name__ == "__main__":
    main(sys.argv[1])
