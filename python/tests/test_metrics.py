"""The eight metrics on numpy arrays, against scikit-image and the closed forms of the paper's appendix."""
import math

import numpy as np
import pytest
from skimage.metrics import peak_signal_noise_ratio, structural_similarity

import matpredict


@pytest.fixture
def pair():
    rng = np.random.default_rng(5)
    truth = rng.random((40, 32, 3), dtype=np.float32)
    prediction = np.clip(truth + rng.normal(0.0, 0.05, truth.shape).astype(np.float32), 0.0, 1.0)
    return truth, prediction


def test_ssim_and_psnr_agree_with_scikit_image(pair):
    truth, prediction = pair
    t64, p64 = truth.astype(np.float64), prediction.astype(np.float64)
    assert matpredict.ssim(truth, prediction) == pytest.approx(
        structural_similarity(t64, p64, data_range=1.0, channel_axis=2), abs=1e-6)
    assert matpredict.psnr(truth, prediction) == pytest.approx(peak_signal_noise_ratio(t64, p64, data_range=1.0), abs=1e-6)
    # A data range of 255 on the same images scaled by 255 is the same score.
    assert matpredict.ssim(truth * 255, prediction * 255, data_range=255.0) == pytest.approx(
        matpredict.ssim(truth, prediction), abs=1e-6)


def test_the_closed_forms_hold(pair):
    truth, prediction = pair
    x, y = truth.astype(np.float64), prediction.astype(np.float64)
    assert matpredict.rmse(truth, prediction) == pytest.approx(math.sqrt(np.mean((y - x) ** 2)), rel=1e-6)
    assert matpredict.sre(truth, prediction) == pytest.approx(10 * math.log10(np.sum(x ** 2) / np.sum((y - x) ** 2)), rel=1e-6)
    assert matpredict.issm(truth, prediction) == pytest.approx(1 / (1 + np.linalg.norm(y - x) / np.linalg.norm(x)), rel=1e-6)
    cosine = np.sum(x * y, axis=2) / (np.linalg.norm(x, axis=2) * np.linalg.norm(y, axis=2))
    angles = np.degrees(np.arccos(np.clip(cosine, -1.0, 1.0)))
    assert matpredict.sam_degrees(truth, prediction) == pytest.approx(angles.mean(), rel=1e-4)
    assert matpredict.psnr(truth, truth) == math.inf
    assert matpredict.uiq(truth, truth) == pytest.approx(1.0)
    assert matpredict.fsim(truth, truth) == pytest.approx(1.0)


def test_a_mask_restricts_the_pixels(pair):
    truth, prediction = pair
    mask = np.zeros(truth.shape[:2], dtype=bool)
    mask[10:30, 8:20] = True
    x, y = truth[mask].astype(np.float64), prediction[mask].astype(np.float64)
    assert matpredict.rmse(truth, prediction, mask=mask) == pytest.approx(math.sqrt(np.mean((y - x) ** 2)), rel=1e-6)
    assert matpredict.rmse(truth, prediction, mask=mask[:, :, None].astype(np.uint8)) == matpredict.rmse(
        truth, prediction, mask=mask)


def test_score_map_gives_the_eight_metrics(pair):
    truth, prediction = pair
    scores = matpredict.score_map(truth, prediction)
    assert list(scores) == ["RMSE", "PSNR", "SRE", "SSIM", "FSIM", "UIQ", "SAM", "ISSM"]
    assert scores["SSIM"] == matpredict.ssim(truth, prediction)
    assert scores["RMSE"] == matpredict.rmse(truth, prediction)
    paper = matpredict.score_map(truth, prediction, convention="paper_compat")
    assert paper["RMSE"] != scores["RMSE"]  # 8-bit quantised, as the paper's package scores


def test_grey_images_and_integer_dtypes_are_read(pair):
    truth, prediction = pair
    grey_truth, grey_prediction = truth[:, :, 0], prediction[:, :, 0]
    assert matpredict.rmse(grey_truth, grey_prediction) == matpredict.rmse(grey_truth[:, :, None], grey_prediction[:, :, None])
    as_bytes = (truth * 255).astype(np.uint8)
    assert matpredict.psnr(as_bytes, as_bytes, data_range=255.0) == math.inf


def test_bad_arrays_raise_clear_errors(pair):
    truth, prediction = pair
    with pytest.raises(ValueError):
        matpredict.rmse(truth, prediction[:, :-1])  # sizes differ
    with pytest.raises(ValueError, match=r"truth: expected an \(H, W\) or \(H, W, C\) array, got shape \(4,\)"):
        matpredict.rmse(np.zeros(4), np.zeros(4))
    with pytest.raises(TypeError, match="prediction: expected an array of numbers"):
        matpredict.rmse(truth, np.full(truth.shape, "a"))
    with pytest.raises(ValueError, match=r"mask: expected shape \(40, 32\)"):
        matpredict.rmse(truth, prediction, mask=np.ones((3, 3)))
    with pytest.raises(ValueError, match="convention"):
        matpredict.score_map(truth, prediction, convention="paper")
    with pytest.raises(ValueError, match="empty"):
        matpredict.rmse(np.zeros((0, 4)), np.zeros((0, 4)))
