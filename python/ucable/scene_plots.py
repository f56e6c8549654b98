"""Pictures of a scene's result: result.png (panels that suit the scene) and the 3-D animation.

result.png has four panels: the tow tension (at the communication points, and its range within
each step); a panel for the kind of scene (towed: the far end's depth; anchored: fairlead and
anchor tension and the grounded length; winch: the paid-out length and the far end's depth); the
side profile of the line at six times; and the plan view (towed) or the remaining quantity.
"""

from __future__ import annotations

import numpy as np

PROFILE_TIMES = 6


def _pyplot():
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    return plt


def profile_indices(n: int, count: int = PROFILE_TIMES) -> list[int]:
    return sorted(set(np.linspace(0, n - 1, min(count, n)).round().astype(int).tolist()))


def side_coordinate(shapes: np.ndarray):
    """The horizontal coordinate of the side profile: x when the line stays in the x-z plane,
    otherwise the horizontal distance from the tow point (a turn, a line across the current)."""
    span_x = np.ptp(shapes[..., 0])
    span_y = np.ptp(shapes[..., 1])
    if span_y <= 0.01 * max(span_x, 1e-9):
        return shapes[..., 0], "x [m]"
    d = shapes[..., :2] - shapes[:, :1, :2]
    return np.hypot(d[..., 0], d[..., 1]), "horizontal distance from the tow point [m]"


def draw_profile(ax, result) -> None:
    shapes = result.shapes()
    if shapes is None:
        ax.text(0.5, 0.5, "no shape recorded (record_shape = false)", ha="center", va="center",
                transform=ax.transAxes)
        return
    h, label = side_coordinate(shapes)
    cmap = _pyplot().get_cmap("viridis")
    idx = profile_indices(len(result.time))
    for j, i in enumerate(idx):
        ax.plot(h[i], shapes[i, :, 2], "-", color=cmap(j / max(len(idx) - 1, 1)), lw=1.5,
                label=f"t = {result.time[i]:g} s")
    p = result.scene.parameters
    if p.get("enableSeabed", False) and "waterDepth" in p:
        ax.axhline(-float(p["waterDepth"]), color="saddlebrown", lw=1.0, label="seabed")
    ax.set_xlabel(label)
    ax.set_ylabel("z [m]")
    ax.set_title("side profile")
    ax.set_aspect("equal", adjustable="datalim")
    ax.legend(fontsize=7)


def plot_result(result, path) -> None:
    plt = _pyplot()
    fig, axes = plt.subplots(2, 2, figsize=(13, 8.5))
    ax = axes.ravel()
    t = result.time
    ax[0].fill_between(t, result["towTensionMin"] / 1e3, result["towTensionMax"] / 1e3, color="tab:blue",
                       alpha=0.25, label="min-max within each step")
    ax[0].plot(t, result["towTension"] / 1e3, color="tab:blue", label="at communication points")
    ax[0].set_ylabel("tow (fairlead) tension [kN]")
    ax[0].legend(fontsize=8)
    kind = result.scene.kind
    depth = -result["endPosition.z"]
    if kind == "anchored":
        ax[1].plot(t, result["towTension"] / 1e3, label="fairlead")
        ax[1].plot(t, result["endTension"] / 1e3, label="anchor")
        ax[1].set_ylabel("tension [kN]")
        ax[1].legend(fontsize=8)
        ax[3].plot(t, result["groundedLength"], color="saddlebrown")
        ax[3].set_ylabel("grounded length [m]")
    elif kind == "winch":
        ax[1].plot(t, result["unstretchedLength"], color="tab:purple")
        ax[1].set_ylabel("paid-out (unstretched) length [m]")
        ax[3].plot(t, depth, color="tab:green")
        ax[3].set_ylabel("far-end depth [m]")
        ax[3].invert_yaxis()
    else:
        ax[1].plot(t, depth, color="tab:green")
        ax[1].set_ylabel("far-end depth [m]")
        ax[1].invert_yaxis()
        ax[3].plot(result["tow.x"], result["tow.y"], label="tow point")
        ax[3].plot(result["endPosition.x"], result["endPosition.y"], label="far end")
        ax[3].set_xlabel("x [m]")
        ax[3].set_ylabel("y [m]")
        ax[3].set_title("plan")
        ax[3].axis("equal")
        ax[3].legend(fontsize=8)
    for i in (0, 1) + ((3,) if kind != "tow" else ()):
        ax[i].set_xlabel("t [s]")
    draw_profile(ax[2], result)
    for a in ax:
        a.grid(alpha=0.3)
    fig.suptitle(result.scene.title)
    fig.tight_layout()
    fig.savefig(path, dpi=100)
    plt.close(fig)


def animate_result(result, path, frames: int = 120) -> None:
    """The 3-D shape over the run as a GIF (Pillow) or, for a .mp4 path, an MP4 (ffmpeg)."""
    plt = _pyplot()
    from matplotlib import animation

    shapes = result.shapes()
    if shapes is None:
        raise ValueError("an animation needs the shape: record_shape = true")
    idx = profile_indices(len(result.time), frames)
    lo, hi = shapes.reshape(-1, 3).min(axis=0), shapes.reshape(-1, 3).max(axis=0)
    fig = plt.figure(figsize=(7, 6))
    ax = fig.add_subplot(projection="3d")
    ax.set_xlim(lo[0], hi[0] + 1e-6)
    ax.set_ylim(lo[1], hi[1] + 1e-6)
    ax.set_zlim(lo[2], hi[2] + 1e-6)
    ax.set_xlabel("x [m]")
    ax.set_ylabel("y [m]")
    ax.set_zlabel("z [m]")
    line, = ax.plot([], [], [], "-o", ms=2, lw=1.5, color="tab:blue")
    label = ax.set_title("")

    def frame(i):
        s = shapes[i]
        line.set_data(s[:, 0], s[:, 1])
        line.set_3d_properties(s[:, 2])
        label.set_text(f"{result.scene.title}\nt = {result.time[i]:.1f} s")
        return line, label

    anim = animation.FuncAnimation(fig, frame, frames=idx, blit=False)
    writer = animation.FFMpegWriter(fps=15) if str(path).endswith(".mp4") else animation.PillowWriter(fps=15)
    anim.save(str(path), writer=writer)
    plt.close(fig)
