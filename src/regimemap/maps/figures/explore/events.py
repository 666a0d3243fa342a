"""The callbacks of :class:`~regimemap.maps.figures.explore.explorer.Explorer`: events -> its plain methods.

Each widget of the explorer (a slider, the check box, *Save*) and a click or a release of the
mouse on its canvas calls one of these handlers, which calls the plain method a test or a
notebook calls directly (:meth:`~regimemap.maps.figures.explore.explorer.Explorer.set_gamma`,
``set_kprime``, ``set_loads``, ``click``, ``save``, ``finish``); a refused value is shown in the
panel rather than raised into the GUI's event loop.  :class:`ExplorerEvents` is the explorer's
base class: the state and the methods it calls are :class:`Explorer`'s (declared below for the
type checker only).
"""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:  # pragma: no cover
    from matplotlib.axes import Axes
    from matplotlib.backend_bases import Event
    from matplotlib.figure import Figure
    from matplotlib.widgets import CheckButtons, Slider

    from ...query import PointResult

__all__ = ["ExplorerEvents"]


class ExplorerEvents:
    """The event handlers of :class:`~regimemap.maps.figures.explore.explorer.Explorer` (its base)."""

    if TYPE_CHECKING:  # what the handlers use of the explorer, defined by Explorer
        fig: Figure
        ax: Axes
        gamma_slider: Slider
        kprime_slider: Slider
        buoyancy_slider: Slider
        nu_slider: Slider
        loads_check: CheckButtons
        _syncing: bool

        def set_gamma(self, value: float, *, final: bool = True) -> None: ...
        def set_kprime(self, value: float, *, final: bool = True) -> None: ...
        def set_loads(self, buoyancy: float | None = None, uplift_ratio: float | None = None, *,
                      enabled: bool | None = None, final: bool = True) -> None: ...
        def click(self, k: float, mu: float) -> PointResult: ...
        def save(self, path: str | Path | None = None) -> Path: ...
        def finish(self) -> None: ...
        def _set_info(self, text: str) -> None: ...
        def _request_draw(self) -> None: ...

    # -- callbacks (events -> the plain methods) ------------------------------------------------
    def _dragging(self) -> bool:
        return any(getattr(s, "drag_active", False) for s in
                   (self.gamma_slider, self.kprime_slider, self.buoyancy_slider, self.nu_slider))

    def _guard(self, action: Callable[[], object]) -> None:
        """Run a widget's action; a refused value is shown in the panel, not raised into the GUI."""
        if self._syncing:
            return
        try:
            action()
        except ValueError as exc:
            self._set_info(f"not shown: {exc}")
            self._request_draw()

    def _on_gamma(self, val: float) -> None:
        self._guard(lambda: self.set_gamma(10.0 ** val, final=not self._dragging()))

    def _on_kprime(self, val: float) -> None:
        self._guard(lambda: self.set_kprime(val, final=not self._dragging()))

    def _on_buoyancy(self, val: float) -> None:
        self._guard(lambda: self.set_loads(buoyancy=val, final=not self._dragging()))

    def _on_nu(self, val: float) -> None:
        self._guard(lambda: self.set_loads(uplift_ratio=val, final=not self._dragging()))

    def _on_check(self, label: str | None) -> None:
        self._guard(lambda: self.set_loads(enabled=bool(self.loads_check.get_status()[0])))

    def _on_save(self, event: Event) -> None:
        try:
            self.save()
        except (OSError, ValueError) as exc:
            self._set_info(f"not saved: {exc}")
            self._request_draw()

    def _on_press(self, event: Any) -> None:
        if event.inaxes is not self.ax or event.button != 1 or event.xdata is None:
            return
        toolbar: Any = getattr(self.fig.canvas, "toolbar", None)
        if toolbar is not None and toolbar.mode:
            return  # zooming or panning
        self._guard(lambda: self.click(event.xdata, event.ydata))

    def _on_release(self, event: Any) -> None:
        self.finish()
