"""A MatPredict dataset as a torch.utils.data.Dataset (Debian's python3-torch), imported on use:
`import matpredict` works without torch.

    from matpredict.torch_data import MaterialDataset
    dataset = MaterialDataset("dataset_out", size=224)
    loader = torch.utils.data.DataLoader(dataset, batch_size=8, num_workers=2)

Each sample is a dict of tensors laid out as libmatlearn's trainer batches them (make_batch): 'input'
(3, S, S) float32 RGB in [0, 1] as stored (no ImageNet normalisation: that is the network's),
'albedo' (3, S, S), 'roughness' and 'metallic' (1, S, S), 'mask' (1, S, S) float32 (1 on the
object), and 'material_id' (S, S) int64 where the dataset has labels; 'id' stays a string.
"""
import torch
import torch.utils.data

from ._core import DatasetReader


class MaterialDataset(torch.utils.data.Dataset):
    """The samples of DatasetReader(root, **options) as tensors (see the module's docstring)."""

    def __init__(self, root, **options):
        self.reader = DatasetReader(root, **options)

    def __len__(self):
        return len(self.reader)

    def __getitem__(self, index):
        sample = self.reader[index]
        tensors = {"id": sample["id"]}
        for name in ("input", "albedo", "roughness", "metallic", "normal"):
            if name in sample:
                tensors[name] = torch.from_numpy(sample[name]).permute(2, 0, 1).contiguous()
        tensors["mask"] = torch.from_numpy(sample["mask"]).to(torch.float32).unsqueeze(0)
        if "material_id" in sample:
            tensors["material_id"] = torch.from_numpy(sample["material_id"]).to(torch.int64)
        return tensors
