"""The six regressors in PyTorch 1.13 (Debian's python3-torch and python3-torchvision), built the
way libmatlearn builds them, timed the way bench/learn_bench.cpp times ours.

Usage: pytorch_regressors.py NETWORK THREADS WARM_UP STEPS SIZE
Prints one JSON line: network, parameters, step_s (median training step, batch 8, Adam, masked
MSE on sigmoid maps per map group), images_per_s (eval-mode forward of batch 8), peak_mib (peak resident size).
"""
import json
import resource
import statistics
import sys
import time

import torch
import torchvision
from torch import nn

BATCH = 8
OUTPUTS = 6


def conv_bn_relu(i, o):
    return nn.Sequential(nn.Conv2d(i, o, 3, padding=1, bias=False), nn.BatchNorm2d(o), nn.ReLU())


def upconv(i, o):
    return nn.Sequential(nn.ConvTranspose2d(i, o, 4, 2, 1, bias=False), nn.BatchNorm2d(o), nn.ReLU())


class UNetNoSkip(nn.Module):
    def __init__(self):
        super().__init__()
        widths, c, enc = [64, 128, 256, 512, 1024], 3, []
        for w in widths:
            enc.append(nn.Sequential(conv_bn_relu(c, w), conv_bn_relu(w, w)))
            c = w
        self.encoder = nn.ModuleList(enc)
        dec = []
        for w in [256, 128, 64, 32]:
            dec.append(upconv(c, w))
            c = w
        self.decoder = nn.Sequential(*dec)
        self.head = nn.Conv2d(c, OUTPUTS, 1)

    def forward(self, x):
        for i, stage in enumerate(self.encoder):
            x = stage(nn.functional.max_pool2d(x, 2) if i else x)
        return self.head(self.decoder(x))


class ResNetTrunk(nn.Module):
    def __init__(self):
        super().__init__()
        r = torchvision.models.resnet50()
        self.conv1, self.bn1, self.layer1, self.layer2, self.layer3, self.layer4 = (
            r.conv1, r.bn1, r.layer1, r.layer2, r.layer3, r.layer4)

    def forward(self, x):
        stem = torch.relu(self.bn1(self.conv1(x)))
        l1 = self.layer1(nn.functional.max_pool2d(stem, 3, 2, 1))
        l2 = self.layer2(l1)
        l3 = self.layer3(l2)
        return stem, l1, l2, l3, self.layer4(l3)


class ResNet50U(nn.Module):
    def __init__(self):
        super().__init__()
        self.encoder = ResNetTrunk()
        self.bottleneck = conv_bn_relu(2048, 512)
        widths, skips, c = [256, 128, 64, 32, 16], [1024, 512, 256, 64, 0], 512
        self.up, self.fuse = nn.ModuleList(), nn.ModuleList()
        for w, s in zip(widths, skips):
            self.up.append(upconv(c, w))
            self.fuse.append(conv_bn_relu(w + s, w))
            c = w
        self.head = nn.Conv2d(c, OUTPUTS, 1)

    def forward(self, x):
        stem, l1, l2, l3, l4 = self.encoder(x)
        skips = [l3, l2, l1, stem]
        x = self.bottleneck(l4)
        for i, (up, fuse) in enumerate(zip(self.up, self.fuse)):
            x = up(x)
            if i < len(skips):
                x = torch.cat([x, skips[i]], 1)
            x = fuse(x)
        return self.head(x)


def stage_outputs(features, x):
    """The outputs of torchvision's features.1, 3, 5 and 7 (the stages between the downsamplings)."""
    stages = []
    for i, layer in enumerate(features):
        x = layer(x)
        if i % 2 == 1:
            stages.append(x)
    return stages


class SwinStages(nn.Module):
    def __init__(self):
        super().__init__()
        s = torchvision.models.swin_t()
        self.features, self.norm = s.features, s.norm

    def forward(self, x):
        stages = stage_outputs(self.features, x)
        stages[3] = self.norm(stages[3])
        return [t.permute(0, 3, 1, 2) for t in stages]


class ConvNeXtStages(nn.Module):
    def __init__(self):
        super().__init__()
        self.features = torchvision.models.convnext_tiny().features

    def forward(self, x):
        return stage_outputs(self.features, x)


class LastStageU(nn.Module):
    def __init__(self, trunk):
        super().__init__()
        self.encoder = trunk
        self.reduce = nn.Sequential(nn.Conv2d(768, 384, 1, bias=False), nn.BatchNorm2d(384), nn.ReLU())
        c, ups = 384, []
        for w in [384, 192, 96, 48, 24]:
            ups.append(upconv(c, w))
            c = w
        self.up = nn.Sequential(*ups)
        self.head = nn.Conv2d(c, OUTPUTS, 1)

    def forward(self, x):
        return self.head(self.up(self.reduce(self.encoder(x)[3])))


class RepoConvBlock(nn.Sequential):
    def __init__(self, i, o):
        super().__init__(nn.Conv2d(i, o, 3, padding=1, bias=False), nn.BatchNorm2d(o), nn.ReLU(),
                         nn.Conv2d(o, o, 3, padding=1, bias=False), nn.BatchNorm2d(o), nn.ReLU())


class RepoUpBlock(nn.Module):
    def __init__(self, i, s, o):
        super().__init__()
        self.up = nn.ConvTranspose2d(i, o, 2, 2)
        self.conv = RepoConvBlock(o + s, o)

    def forward(self, x, skip):
        x = self.up(x)
        if x.shape[-2:] != skip.shape[-2:]:
            x = nn.functional.interpolate(x, size=skip.shape[-2:], mode="bilinear", align_corners=False)
        return self.conv(torch.cat([x, skip], 1))


class RepoResNet50UNet(nn.Module):
    def __init__(self):
        super().__init__()
        self.encoder = ResNetTrunk()
        self.bottleneck = RepoConvBlock(2048, 1024)
        self.up4, self.up3 = RepoUpBlock(1024, 1024, 512), RepoUpBlock(512, 512, 256)
        self.up2, self.up1 = RepoUpBlock(256, 256, 128), RepoUpBlock(128, 64, 64)
        self.final_up, self.final_conv = nn.ConvTranspose2d(64, 32, 2, 2), RepoConvBlock(32, 32)
        self.head = nn.Conv2d(32, OUTPUTS, 1)

    def forward(self, x):
        stem, l1, l2, l3, l4 = self.encoder(x)
        x = self.up1(self.up2(self.up3(self.up4(self.bottleneck(l4), l3), l2), l1), stem)
        return self.head(self.final_conv(self.final_up(x)))


class RepoSwinTUNet(nn.Module):
    def __init__(self):
        super().__init__()
        self.encoder = SwinStages()
        self.bottleneck = RepoConvBlock(768, 768)
        self.up4, self.up3, self.up2 = RepoUpBlock(768, 384, 384), RepoUpBlock(384, 192, 192), RepoUpBlock(192, 96, 96)
        self.up1, self.conv1 = nn.ConvTranspose2d(96, 64, 2, 2), RepoConvBlock(64, 64)
        self.final_up, self.final_conv = nn.ConvTranspose2d(64, 32, 2, 2), RepoConvBlock(32, 32)
        self.head = nn.Conv2d(32, OUTPUTS, 1)

    def forward(self, x):
        f1, f2, f3, f4 = self.encoder(x)
        x = self.up2(self.up3(self.up4(self.bottleneck(f4), f3), f2), f1)
        x = self.conv1(self.up1(x))
        return self.head(self.final_conv(self.final_up(x)))


NETWORKS = {
    "unet_no_skip": UNetNoSkip,
    "resnet50_u": ResNet50U,
    "swin_t_u": lambda: LastStageU(SwinStages()),
    "convnext_t_u": lambda: LastStageU(ConvNeXtStages()),
    "repo_resnet50_unet": RepoResNet50UNet,
    "repo_swin_t_unet": RepoSwinTUNet,
}


def main():
    name, threads, warm_up, steps, size = sys.argv[1], int(sys.argv[2]), int(sys.argv[3]), int(sys.argv[4]), int(sys.argv[5])
    torch.set_num_threads(threads)
    torch.manual_seed(0)
    model = NETWORKS[name]()
    optimizer = torch.optim.Adam(model.parameters(), lr=2e-4)
    image = torch.rand(BATCH, 3, size, size)
    target = torch.rand(BATCH, OUTPUTS, size, size)
    mask = torch.ones(BATCH, 1, size, size)
    model.train()
    times = []
    for step in range(warm_up + steps):
        start = time.perf_counter()
        optimizer.zero_grad()
        maps = torch.sigmoid(model(image))
        # libmatlearn's paper layout: base colour and roughness, 3 channels each, a term each.
        loss = sum(((maps[:, a:a + 3] - target[:, a:a + 3]) ** 2 * mask).sum() / (mask.sum() * 3) for a in (0, 3))
        loss.backward()
        optimizer.step()
        if step >= warm_up:
            times.append(time.perf_counter() - start)
    model.eval()
    forward = []
    with torch.no_grad():
        for step in range(warm_up + steps):
            start = time.perf_counter()
            model(image)
            if step >= warm_up:
                forward.append(time.perf_counter() - start)
    print(json.dumps({"network": name, "parameters": sum(p.numel() for p in model.parameters()),
                      "step_s": statistics.median(times), "images_per_s": BATCH / statistics.median(forward),
                      "peak_mib": resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024.0}))


if __name__ == "__main__":
    main()
