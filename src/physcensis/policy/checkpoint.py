"""A trained policy read back from its folder: environment observations in, environment actions out."""

from __future__ import annotations

import json
from collections.abc import Mapping
from pathlib import Path
from typing import Any

import numpy as np

from physcensis.policy.backend import PolicyError, load_learner
from physcensis.policy.features import ActionScale, decode_action, with_derived
from physcensis.policy.train import FORMAT, POLICY, make_model


class Policy:
    """robomimic's RolloutPolicy around a trained BC model, with physcensis's observation and action maps."""

    def __init__(self, rollout: Any, scale: ActionScale, keys: tuple[str, ...]) -> None:
        self._rollout = rollout
        self.scale = scale
        self.keys = keys

    def reset(self) -> None:
        """Start an episode (BC-RNN forgets its state)."""
        self._rollout.start_episode()

    def act(self, obs: Mapping[str, np.ndarray]) -> np.ndarray:
        """The 8-number environment action for one observation of `physcensis/PickPlace-v0`."""
        import torch

        features = with_derived(obs)
        with torch.no_grad():
            scaled = self._rollout(ob={key: features[key] for key in self.keys})
        return decode_action(np.clip(scaled, -1.0, 1.0), np.asarray(obs["joint_pos"]), self.scale)


def load_policy(folder: str | Path) -> Policy:
    """The policy `physcensis policy train` wrote to `folder` (or the policy.pth file itself)."""
    path = Path(folder)
    path = path / POLICY if path.is_dir() else path
    if not path.is_file():
        raise PolicyError(f"{path}: no trained policy there (give the folder `physcensis policy train` wrote)")
    load_learner()
    import torch
    from robomimic.algo import RolloutPolicy
    from robomimic.config import config_factory

    try:
        # weights_only: tensors, numbers, strings, lists and dicts only; a checkpoint never runs code when read
        checkpoint = torch.load(path, map_location="cpu", weights_only=True)
        extra = checkpoint["physcensis"]
    except Exception as exc:  # torch raises many kinds for a file that is not its own
        raise PolicyError(f"{path}: not a physcensis policy checkpoint ({exc.__class__.__name__})") from None
    if extra.get("format") != FORMAT:
        raise PolicyError(f"{path}: written in format {extra.get('format')!r}; this physcensis reads {FORMAT!r}")
    config = config_factory(checkpoint["algo_name"], dic=json.loads(checkpoint["config"]))
    model = make_model(config, checkpoint["shape_metadata"]["all_shapes"])
    model.deserialize(checkpoint["model"])
    stats = {
        key: {name: np.asarray(values, dtype=np.float32) for name, values in entry.items()}
        for key, entry in checkpoint["obs_normalization_stats"].items()
    }
    rollout = RolloutPolicy(model, obs_normalization_stats=stats)
    return Policy(rollout, ActionScale.from_dict(extra["action_scale"]), tuple(extra["obs_keys"]))
