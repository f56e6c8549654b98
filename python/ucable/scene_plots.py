"""Pictures of a scene's result: result.png (panels that suit the kind of scene) and the animation.

result.png has six panels. Every kind has the side profile of the line at six times with the seabed
(when the FMU has one) and the range graph: the envelope (min to max over the run) of the tension and
of the curvature along the line, from the station outputs. The others suit the scene:

- towing: the tow tension (its range within each step), the far end's depth and the layback, the top
  angle, the plan view (the tow point's track, the far end's, the line at six times);
- winch: the tension, the paid-out length, the far end's depth, the plan view;
- anchored line: fairlead and anchor tension, the grounded length, the fairlead's motion, the plan view;
- mooring system ([body]): each line's fairlead and anchor tension, the lines' force on the body, the
  body's motion, the plan view with the body's track; without recorded stations the profile and the
  range graph give way to each line's grounded length and tension range.

The animation shows the line's side and plan views to equal scale, coloured by tension, with the tow
point (vessel or fairlead), the far end or body, the surface and the seabed, rendered with a progress bar.
"""

from __future__ import annotations

import numpy as np

from .fmu import NUM_STATIONS
from .summary import line_numbers

PROFILE_TIMES = 6
KIND_TITLES = {"tow": "tow", "winch": "winch", "anchored": "anchored line", "mooring": "mooring system"}


def _pyplot():
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    return plt


def profile_indices(n: int, count: int = PROFILE_TIMES) -> list[int]:
    return sorted(set(np.linspace(0, n - 1, min(count, n)).round().astype(int).tolist()))


def plot_kind(result) -> str:
    """'mooring' (a scene moving body 1 of a deck), else the scene's kind: 'tow', 'winch', 'anchored'."""
    return "mooring" if result.scene.body else result.scene.kind


def side_coordinate(shapes: np.ndarray):
    """The horizontal coordinate of the side profile: x when the line stays in the x-z plane,
    otherwise the horizontal distance from the tow point (a turn, a line across the current)."""
    span_x = np.ptp(shapes[..., 0])
    span_y = np.ptp(shapes[..., 1])
    if span_y <= 0.01 * max(span_x, 1e-9):
        return shapes[..., 0], "x [m]"
    d = shapes[..., :2] - shapes[:, :1, :2]
    return np.hypot(d[..., 0], d[..., 1]), "horizontal distance from the tow point [m]"


def station_table(result, quantity: str) -> np.ndarray | None:
    """The recorded `quantity`[k] (tension, curvature) at every station, [time, station], or None."""
    names = [f"{quantity}[{k}]" for k in range(1, NUM_STATIONS + 1)]
    if not all(n in result.columns for n in names):
        return None
    return np.column_stack([result[n] for n in names])


def arc_length(shape: np.ndarray) -> np.ndarray:
    """Distance along the stations of one shape [station, xyz], from the tow point."""
    return np.concatenate([[0.0], np.cumsum(np.linalg.norm(np.diff(shape, axis=0), axis=1))])


def _seabed(ax, result, horizontal: bool = True) -> None:
    if result.seabed is not None and horizontal:
        ax.axhline(-result.seabed, color="saddlebrown", lw=1.2, label=f"seabed ({result.seabed:g} m)")


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
    _seabed(ax, result)
    ax.axhline(0.0, color="tab:blue", lw=0.6, alpha=0.6)
    ax.set_xlabel(label)
    ax.set_ylabel("z [m]")
    ax.set_title("side profile")
    ax.set_aspect("equal", adjustable="datalim")
    ax.legend(fontsize=7)


def draw_range(ax, result) -> bool:
    """The range graph: tension (and curvature, right axis) envelope along the line over the run;
    False when the stations were not recorded."""
    T = station_table(result, "tension")
    shapes = result.shapes()
    if T is None or shapes is None:
        return False
    L = result.columns.get("unstretchedLength")
    if L is not None and np.ptp(L) > 1e-6 * max(abs(L[0]), 1.0):  # the stations move along a changing length
        s, xlabel = np.linspace(0.0, 1.0, NUM_STATIONS), "fraction of the paid-out length from the tow point"
    else:
        s, xlabel = arc_length(shapes[0]), "arc length from the tow point at t = 0 [m]"
    ax.fill_between(s, T.min(axis=0) / 1e3, T.max(axis=0) / 1e3, color="tab:blue", alpha=0.25,
                    label="tension min-max over the run")
    ax.plot(s, T[-1] / 1e3, color="tab:blue", lw=1.2, label=f"tension at t = {result.time[-1]:g} s")
    ax.set_xlabel(xlabel)
    ax.set_ylabel("tension [kN]", color="tab:blue")
    ax.set_title("range graph")
    K = station_table(result, "curvature")
    if K is not None:
        a2 = ax.twinx()
        a2.fill_between(s, K.min(axis=0), K.max(axis=0), color="tab:red", alpha=0.2)
        a2.plot(s, K.max(axis=0), color="tab:red", lw=1.0, label="curvature max over the run")
        a2.set_ylabel("curvature [1/m] (band: min-max)", color="tab:red")
        a2.legend(fontsize=7, loc="upper right")
    ax.legend(fontsize=7, loc="upper left")
    return True


def draw_plan(ax, result, vessel: tuple[str, str], vessel_label: str, far: tuple[str, str] | None,
              far_label: str = "far end") -> None:
    """Plan view: the vessel's (tow point's, body's) track, the far end's, the line at six times."""
    c = result.columns
    ax.plot(c[vessel[0]], c[vessel[1]], color="k", lw=1.5, label=f"{vessel_label} track")
    ax.plot(c[vessel[0]][-1], c[vessel[1]][-1], "k^", ms=8)
    if far is not None:
        ax.plot(c[far[0]], c[far[1]], color="tab:green", lw=1.2, label=f"{far_label} track")
    shapes = result.shapes()
    if shapes is not None:
        cmap = _pyplot().get_cmap("viridis")
        idx = profile_indices(len(result.time))
        for j, i in enumerate(idx):
            ax.plot(shapes[i, :, 0], shapes[i, :, 1], "-", color=cmap(j / max(len(idx) - 1, 1)), lw=0.8, alpha=0.8)
    ax.set_xlabel("x [m]")
    ax.set_ylabel("y [m]")
    ax.set_title("plan view" + (" (line at six times)" if shapes is not None else ""))
    ax.set_aspect("equal", adjustable="datalim")
    ax.legend(fontsize=7)


def draw_tow_tension(ax, result, label: str = "tow tension") -> None:
    t = result.time
    ax.fill_between(t, result["towTensionMin"] / 1e3, result["towTensionMax"] / 1e3, color="tab:blue",
                    alpha=0.25, label="min-max within each step")
    ax.plot(t, result["towTension"] / 1e3, color="tab:blue", label=f"{label} at communication points")
    ax.set_ylabel(f"{label} [kN]")
    ax.legend(fontsize=7)


def _time_axis(ax, t) -> None:
    ax.set_xlabel("t [s]")
    ax.set_xlim(t[0], max(t[-1], t[0] + 1e-9))


def _tow_panels(ax, result) -> None:
    t, c = result.time, result.columns
    draw_tow_tension(ax[0], result)
    depth = -result["endPosition.z"]
    ax[1].plot(t, depth, color="tab:green", label="far-end depth")
    ax[1].set_ylabel("far-end (fish) depth [m]", color="tab:green")
    ax[1].invert_yaxis()
    if "layback" in c:
        a2 = ax[1].twinx()
        a2.plot(t, c["layback"], color="tab:orange", ls="--", label="layback")
        a2.set_ylabel("layback [m]", color="tab:orange")
    if "unstretchedLength" in c:
        ax[2].plot(t, c["unstretchedLength"], color="tab:purple")
        ax[2].set_ylabel("paid-out (unstretched) length [m]")
    elif "topDeclination" in c:
        ax[2].plot(t, np.degrees(c["topDeclination"]), color="tab:red")
        ax[2].set_ylabel("top angle from the vertical [deg]")
    for i in (0, 1, 2):
        _time_axis(ax[i], t)
    draw_plan(ax[3], result, ("tow.x", "tow.y"), "tow point", ("endPosition.x", "endPosition.y"))


def _anchored_panels(ax, result) -> None:
    t, c = result.time, result.columns
    draw_tow_tension(ax[0], result, "fairlead tension")
    ax[0].plot(t, c["endTension"] / 1e3, color="tab:orange", label="anchor tension")
    ax[0].set_ylabel("tension [kN]")
    ax[0].legend(fontsize=7)
    ax[1].plot(t, c["groundedLength"], color="saddlebrown")
    ax[1].set_ylabel("grounded length [m]")
    for q, color in zip("xyz", ("tab:blue", "tab:orange", "tab:green")):
        ax[2].plot(t, c[f"tow.{q}"] - c[f"tow.{q}"][0], color=color, label=f"{q} from {c[f'tow.{q}'][0]:g} m")
    ax[2].set_ylabel("fairlead motion [m]")
    ax[2].legend(fontsize=7)
    for i in (0, 1, 2):
        _time_axis(ax[i], t)
    draw_plan(ax[3], result, ("tow.x", "tow.y"), "fairlead", None)


def _mooring_panels(ax, result) -> None:
    t, c = result.time, result.columns
    for k in line_numbers(c):
        color = f"C{(k - 1) % 10}"
        ax[0].plot(t, c[f"line[{k}].fairleadTension"] / 1e3, color=color, label=f"line {k} fairlead")
        ax[0].plot(t, c[f"line[{k}].anchorTension"] / 1e3, color=color, ls="--", lw=0.8, label=f"line {k} anchor")
    ax[0].set_ylabel("tension [kN]")
    ax[0].set_title("line tensions")
    ax[0].legend(fontsize=7, ncol=2)
    for q, color in zip("xyz", ("tab:blue", "tab:orange", "tab:green")):
        ax[1].plot(t, c[f"body[1].force.{q}"] / 1e3, color=color, label=f"F{q}")
    ax[1].set_ylabel("lines' force on body 1 [kN]")
    ax[1].legend(fontsize=7)
    for q, color in zip("xyz", ("tab:blue", "tab:orange", "tab:green")):
        ax[2].plot(t, c[f"body[1].{q}"], color=color, label=f"{q} [m]")
    ax[2].set_ylabel("body 1 position [m]")
    a2 = ax[2].twinx()
    for q, color in zip(("roll", "pitch", "yaw"), ("tab:red", "tab:purple", "tab:brown")):
        a2.plot(t, np.degrees(c[f"body[1].{q}"]), color=color, ls=":", label=f"{q} [deg]")
    a2.set_ylabel("body 1 angles [deg] (dotted)")
    ax[2].legend(fontsize=7, loc="upper left")
    a2.legend(fontsize=7, loc="upper right")
    ax[2].set_title("body motion")
    for i in (0, 1, 2):
        _time_axis(ax[i], t)
    draw_plan(ax[3], result, ("body[1].x", "body[1].y"), "body 1 (vessel)", None)


def _lines_without_stations(ax_profile, ax_range, result) -> None:
    """A mooring without recorded stations: each line's grounded length and each line's tension range."""
    t, c = result.time, result.columns
    ks = line_numbers(c)
    for k in ks:
        if f"line[{k}].groundedLength" in c:
            ax_profile.plot(t, c[f"line[{k}].groundedLength"], color=f"C{(k - 1) % 10}", label=f"line {k}")
    ax_profile.set_ylabel("length resting on the seabed [m]")
    ax_profile.set_title("grounded length" + (f" (seabed {result.seabed:g} m deep)" if result.seabed else ""))
    _time_axis(ax_profile, t)
    ax_profile.legend(fontsize=7)
    x = np.arange(len(ks))
    for j, (end, color) in enumerate((("fairlead", "tab:blue"), ("anchor", "tab:orange"))):
        lo = [np.min(c[f"line[{k}].{end}Tension"]) / 1e3 for k in ks]
        hi = [np.max(c[f"line[{k}].{end}Tension"]) / 1e3 for k in ks]
        ax_range.bar(x + (j - 0.5) * 0.35, np.subtract(hi, lo), 0.35, bottom=lo, color=color, alpha=0.6,
                     label=f"{end}: min-max")
    ax_range.set_xticks(x)
    ax_range.set_xticklabels([f"line {k}" for k in ks])
    ax_range.set_ylabel("tension [kN]")
    ax_range.set_title("tension range per line (no stations recorded: record_shape = false)")
    ax_range.legend(fontsize=7)


def plot_result(result, path) -> None:
    plt = _pyplot()
    fig = result_figure(result)
    fig.savefig(path, dpi=90)
    plt.close(fig)


def result_figure(result):
    """The figure of result.png (the caller saves and closes it)."""
    plt = _pyplot()
    fig, axes = plt.subplots(3, 2, figsize=(13, 12.5))
    ax = axes.ravel()
    kind = plot_kind(result)
    {"mooring": _mooring_panels, "anchored": _anchored_panels}.get(kind, _tow_panels)(ax, result)
    if kind == "mooring" and result.shapes() is None:
        _lines_without_stations(ax[4], ax[5], result)
    else:
        draw_profile(ax[4], result)
        if not draw_range(ax[5], result):
            ax[5].text(0.5, 0.5, "no stations recorded (record_shape = false)", ha="center", va="center",
                       transform=ax[5].transAxes)
    for a in ax:
        a.grid(alpha=0.3)
    fig.suptitle(f"{result.scene.title} ({KIND_TITLES[kind]})")
    fig.tight_layout()
    return fig


# ------------------------------------------------------------------------------------ animation
def _limits(values: np.ndarray, pad: float = 0.05) -> tuple[float, float]:
    lo, hi = float(np.nanmin(values)), float(np.nanmax(values))
    d = max(hi - lo, 1.0) * pad
    return lo - d, hi + d


def animate_result(result, path, frames: int = 120, progress: bool = False) -> None:
    """The line over the run as a GIF (Pillow) or, for a .mp4 path, an MP4 (ffmpeg): side view (x-z, or
    the horizontal distance from the tow point when the line turns) and plan view (x-y) to equal scale,
    the line coloured by its tension (the stations' tension; one colour without them), the tow point
    (vessel or fairlead) and its track, the far end (a body's marker), the surface and the seabed. With
    `progress` a progress bar on stderr. The axes, ticks, tracks and seabed are drawn once; each frame
    draws the moving artists over that background (the cost of a frame is the line, not the figure)."""
    plt = _pyplot()
    from matplotlib.collections import LineCollection

    from .progress import ProgressBar

    shapes = result.shapes()
    if shapes is None:
        raise ValueError("an animation needs the shape: record_shape = true")
    idx = profile_indices(len(result.time), frames)
    h, hlabel = side_coordinate(shapes)
    T = station_table(result, "tension")
    tension = None if T is None else 0.5 * (T[:, 1:] + T[:, :-1]) / 1e3  # per segment, kN
    fig, (side, plan) = plt.subplots(1, 2, figsize=(11, 5), layout="constrained")
    zlo = [-result.seabed * 1.03] if result.seabed is not None else []
    zmin, zmax = _limits(np.concatenate([shapes[..., 2].ravel(), [0.0], zlo]))
    side.set_xlim(*_limits(h))
    side.set_ylim(zmin, zmax)
    side.axhline(0.0, color="tab:blue", lw=1.0, alpha=0.6)
    if result.seabed is not None:
        side.axhspan(zmin, -result.seabed, color="saddlebrown", alpha=0.35, lw=0)
        side.axhline(-result.seabed, color="saddlebrown", lw=1.2, label="seabed")
    side.set_xlabel(hlabel)
    side.set_ylabel("z [m]")
    c = result.columns
    body = "body[1].x" in c
    vx, vy = (c["body[1].x"], c["body[1].y"]) if body else (c["tow.x"], c["tow.y"])
    xlim = _limits(np.concatenate([shapes[..., 0].ravel(), vx]))
    ylo, yhi = _limits(np.concatenate([shapes[..., 1].ravel(), vy]))
    half = max(0.5 * (yhi - ylo), 0.15 * (xlim[1] - xlim[0]))  # a line in the x-z plane: a strip, not a hair
    plan.set_xlim(*xlim)
    plan.set_ylim(0.5 * (ylo + yhi) - half, 0.5 * (ylo + yhi) + half)
    plan.set_xlabel("x [m]")
    plan.set_ylabel("y [m]")
    plan.plot(vx, vy, color="0.6", lw=1.0, label="body 1 track" if body else "tow point (vessel) track")
    for a in (side, plan):
        a.set_aspect("equal", adjustable="box")
        a.grid(alpha=0.3)
    norm = plt.Normalize(*(_limits(tension, 0.0) if tension is not None else (0.0, 1.0)))
    lines = [LineCollection([], cmap="plasma", norm=norm, lw=2.5, animated=True) for _ in (side, plan)]
    for a, lc in zip((side, plan), lines):
        if tension is None:
            lc.set_color("tab:blue")
        a.add_collection(lc)
    if tension is not None:
        fig.colorbar(lines[0], ax=[side, plan], label="tension [kN]", shrink=0.7)
    top_side, = side.plot([], [], "kv", ms=10, label="tow point (vessel, fairlead)", animated=True)
    end_side, = side.plot([], [], "s", color="tab:green", ms=7, label="far end", animated=True)
    top_plan, = plan.plot([], [], "k^", ms=9, animated=True)
    end_plan, = plan.plot([], [], "s", color="tab:green", ms=6, animated=True)
    side.legend(fontsize=7)
    plan.legend(fontsize=7)
    label = fig.suptitle("", animated=True)
    moving = [*lines, top_side, end_side, top_plan, end_plan, label]

    def frame(i):
        s = shapes[i]
        for lc, xy in zip(lines, (np.column_stack([h[i], s[:, 2]]), s[:, :2])):
            lc.set_segments(np.stack([xy[:-1], xy[1:]], axis=1))
            if tension is not None:
                lc.set_array(tension[i])
        top_side.set_data([h[i, 0]], [s[0, 2]])
        end_side.set_data([h[i, -1]], [s[-1, 2]])
        top_plan.set_data([s[0, 0]], [s[0, 1]])
        end_plan.set_data([s[-1, 0]], [s[-1, 1]])
        label.set_text(f"{result.scene.title}\nt = {result.time[i]:.1f} s")

    bar = ProgressBar(len(idx), label="animation") if progress else None
    images = render_frames(fig, moving, frame, idx, dpi=72,
                           progress=(lambda k: bar.update(k, f"frame {k}/{len(idx)}")) if bar else None)
    plt.close(fig)
    write_movie(images, path, fps=15)
    if bar:
        bar.close(f"{len(idx)} frames")


def render_frames(fig, moving: list, frame, indices, dpi: float, progress=None) -> list:
    """Frames as RGB images: the figure without its `moving` (animated) artists drawn once, then for each
    index frame(i) updates them and they are drawn over a copy of that background."""
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from PIL import Image

    fig.set_dpi(dpi)
    canvas = FigureCanvasAgg(fig)
    canvas.draw()
    background = canvas.copy_from_bbox(fig.bbox)
    images = []
    for k, i in enumerate(indices, start=1):
        frame(i)
        canvas.restore_region(background)
        for artist in moving:
            fig.draw_artist(artist)
        images.append(Image.fromarray(np.asarray(canvas.buffer_rgba())[..., :3].copy()))
        if progress is not None:
            progress(k)
    return images


def write_movie(images: list, path, fps: float) -> None:
    """A GIF (Pillow; one palette for every frame, so the colours do not flicker) or, for a .mp4 path, an
    MP4 through ffmpeg."""
    path = str(path)
    if path.endswith(".mp4"):
        import subprocess

        w, h = images[0].size
        cmd = ["ffmpeg", "-y", "-loglevel", "error", "-f", "rawvideo", "-pix_fmt", "rgb24", "-s", f"{w}x{h}",
               "-r", str(fps), "-i", "-", "-vf", "pad=ceil(iw/2)*2:ceil(ih/2)*2", "-pix_fmt", "yuv420p", path]
        subprocess.run(cmd, input=b"".join(im.tobytes() for im in images), check=True)
        return
    palette = images[len(images) // 2].quantize(colors=255)
    frames = [im.quantize(palette=palette, dither=0) for im in images]
    frames[0].save(path, save_all=True, append_images=frames[1:], duration=int(round(1000 / fps)), loop=0)
