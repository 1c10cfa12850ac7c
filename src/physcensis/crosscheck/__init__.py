"""The cross-check: a scene verified in MuJoCo settled again in a second engine (PyBullet), through its export."""
