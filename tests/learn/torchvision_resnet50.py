"""torchvision 0.14's resnet50 trunk, the reference for tests/learn/resnet_encoder_test.cpp.

Usage: torchvision_resnet50.py OUT_DIR
Writes names.txt (name and shape, "(64,3,7,7)" or "()", of every parameter and buffer, the
classifier left out),
torchvision.pth (the whole state dict: torchvision's random initialisation with seed 0, the
BatchNorm affine parameters and running statistics randomised too so that they matter) and io.pt (a
1x3x64x64 input and the eval-mode feature maps stem, layer1 .. layer4).
"""
import sys

import torch
import torchvision

out = sys.argv[1]
torch.manual_seed(0)
model = torchvision.models.resnet50().eval()
with torch.no_grad():
    for module in model.modules():
        if isinstance(module, torch.nn.BatchNorm2d):
            module.weight.copy_(1.0 + 0.1 * torch.randn_like(module.weight))
            module.bias.copy_(0.1 * torch.randn_like(module.bias))
            module.running_mean.copy_(0.1 * torch.randn_like(module.running_mean))
            module.running_var.copy_(0.5 + torch.rand_like(module.running_var))
# torchvision's own layout, classifier included: the test converts it with
# scripts/convert_torchvision_weights.py as a user would.
torch.save(model.state_dict(), f"{out}/torchvision.pth")
state = {k: v for k, v in model.state_dict().items() if not k.startswith("fc.")}
with open(f"{out}/names.txt", "w") as names:
    for name, tensor in state.items():
        names.write(f"{name} ({','.join(str(s) for s in tensor.shape)})\n")

x = torch.randn(1, 3, 64, 64)
with torch.no_grad():
    stem = model.relu(model.bn1(model.conv1(x)))
    layer1 = model.layer1(model.maxpool(stem))
    layer2 = model.layer2(layer1)
    layer3 = model.layer3(layer2)
    layer4 = model.layer4(layer3)
torch.save({"input": x, "stem": stem, "layer1": layer1, "layer2": layer2, "layer3": layer3, "layer4": layer4},
           f"{out}/io.pt")
