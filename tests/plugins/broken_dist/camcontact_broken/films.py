"""Film models that load but misbehave when they run."""

from camcontact.models.base import FilmModel


class LineFilm(FilmModel):
    """Base of the test films: a line film of the usual inputs."""

    reference = "none (a test plugin)"
    requires = ("R", "w", "E_reduced", "u_m", "eta0", "alpha")
    provides = ("h_c", "h_min")


class NanFilm(LineFilm):
    """Returns NaN and -inf films."""

    name = "nan_film"

    def evaluate(self, R, w, E_reduced, u_m, eta0, alpha):
        return {"h_c": float("nan"), "h_min": float("-inf")}


class RaisingFilm(LineFilm):
    """Raises KeyError while it runs (a bug of its own)."""

    name = "raising_film"

    def evaluate(self, R, w, E_reduced, u_m, eta0, alpha):
        return {"h_c": {}["h_c"]}


class NegativeFilm(LineFilm):
    """Returns a negative central film."""

    name = "negative_film"
    provides = ("h_c",)

    def evaluate(self, R, w, E_reduced, u_m, eta0, alpha):
        return {"h_c": -1e-7}


class FirstTwin(LineFilm):
    """A working film model whose class name is the same as SecondTwin's: reached by its entry-point name."""

    name = "twin"
    provides = ("h_c",)

    def evaluate(self, R, w, E_reduced, u_m, eta0, alpha):
        return {"h_c": 1e-6}


class SecondTwin(FirstTwin):
    """See FirstTwin."""

    def evaluate(self, R, w, E_reduced, u_m, eta0, alpha):
        return {"h_c": 2e-6}
