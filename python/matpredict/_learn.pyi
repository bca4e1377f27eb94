"""Type stubs of matpredict's trained-network module (imported by matpredict.load_model)."""
from typing import Dict, List

import numpy as np
import numpy.typing as npt

class Model:
    """A trained regressor, as evaluate loads it."""
    @property
    def network(self) -> str: ...
    @property
    def image_size(self) -> int: ...
    @property
    def outputs(self) -> List[str]: ...
    @property
    def linear_albedo(self) -> bool: ...
    @property
    def epochs_done(self) -> int: ...
    def predict(self, image: npt.ArrayLike) -> Dict[str, npt.NDArray[np.float32]]:
        """The maps for one (image_size, image_size, 3) RGB image in [0, 1]."""

def load_model(path: str) -> Model:
    """Reads and verifies a checkpoint and builds its network."""
