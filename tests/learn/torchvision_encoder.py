"""A torchvision 0.14 encoder, the reference for tests/learn/*_encoder_test.cpp.

Usage: torchvision_encoder.py MODEL OUT_DIR     MODEL: resnet50, swin_t or convnext_tiny
Writes into OUT_DIR:
  names.txt        name and shape ("(64,3,7,7)", "()" for a scalar) of every parameter and buffer,
                   the classifier left out;
  torchvision.pth  the whole state dict: torchvision's random initialisation with seed 0, and the
                   normalisation parameters, running statistics, layer scales and position biases
                   randomised too so that they matter;
  io.pt            a 1x3x96x64 input and the eval-mode stage outputs (NCHW), named stem, layer1 ..
                   layer4 for resnet50 and stage1 .. stage4 for the others (swin_t's stage4 after
                   its final norm).
"""
import sys

import torch
import torchvision

CLASSIFIERS = {"resnet50": ("fc.",), "swin_t": ("head.",), "convnext_tiny": ("classifier.",)}


def randomise(model):
    with torch.no_grad():
        for module in model.modules():
            if isinstance(module, (torch.nn.BatchNorm2d, torch.nn.LayerNorm)):
                module.weight.copy_(1.0 + 0.1 * torch.randn_like(module.weight))
                module.bias.copy_(0.1 * torch.randn_like(module.bias))
            if isinstance(module, torch.nn.BatchNorm2d):
                module.running_mean.copy_(0.1 * torch.randn_like(module.running_mean))
                module.running_var.copy_(0.5 + torch.rand_like(module.running_var))
        for name, parameter in model.named_parameters():
            if name.endswith("layer_scale"):
                parameter.copy_(0.5 + 0.1 * torch.randn_like(parameter))
            if name.endswith("relative_position_bias_table"):
                parameter.copy_(torch.randn_like(parameter))


def stage_outputs(name, model, x):
    if name == "resnet50":
        stem = model.relu(model.bn1(model.conv1(x)))
        layer1 = model.layer1(model.maxpool(stem))
        layer2 = model.layer2(layer1)
        layer3 = model.layer3(layer2)
        return {"stem": stem, "layer1": layer1, "layer2": layer2, "layer3": layer3, "layer4": model.layer4(layer3)}
    outputs = {}
    for index, layer in enumerate(model.features):
        x = layer(x)
        if index % 2 == 1:
            outputs[f"stage{index // 2 + 1}"] = x
    if name == "swin_t":
        outputs["stage4"] = model.norm(outputs["stage4"])
        outputs = {key: value.permute(0, 3, 1, 2) for key, value in outputs.items()}
    return outputs


def main():
    name, out = sys.argv[1], sys.argv[2]
    torch.manual_seed(0)
    model = getattr(torchvision.models, name)().eval()
    randomise(model)
    # torchvision's own layout, classifier included: the tests convert it with
    # scripts/convert_torchvision_weights.py as a user would.
    torch.save(model.state_dict(), f"{out}/torchvision.pth")
    with open(f"{out}/names.txt", "w") as names:
        for key, tensor in model.state_dict().items():
            if not key.startswith(CLASSIFIERS[name]):
                names.write(f"{key} ({','.join(str(s) for s in tensor.shape)})\n")
    x = torch.randn(1, 3, 96, 64)
    with torch.no_grad():
        io = {key: value.contiguous() for key, value in stage_outputs(name, model, x).items()}
    io["input"] = x
    torch.save(io, f"{out}/io.pt")


if __name__ == "__main__":
    main()
