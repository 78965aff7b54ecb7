"""Keyword arguments onto the settings objects of the compiled module, by table: each option
names the attribute path it sets, so that the library's defaults stay where they are defined
and an unknown or ill-typed option fails with one line naming it."""

# The engine's parameters (aco/variants.hpp) under the names of the antslam program's options.
ENGINE = {
    "ants": "ants", "alpha": "alpha", "beta": "beta", "rho": "rho", "q0": "q0", "xi": "xi",
    "elite_weight": "elite_weight", "rank_width": "rank_width", "p_best": "p_best",
    "restarts": "restarts", "restart_stagnant": "restart_stagnant", "p0": "p0", "glob_best_freq": "glob_best_freq",
    "tau_max": "tau_max", "tau_init": "tau_init", "ls_ants": "local_search_ants",
}


def apply(target, table, options, function):
    """Sets target.<path> = value for every option (table: option -> dotted attribute path)."""
    for name, value in options.items():
        if name not in table:
            raise TypeError(f"{function}() got an unexpected keyword argument '{name}'")
        *parents, attribute = table[name].split(".")
        owner = target
        for parent in parents:
            owner = getattr(owner, parent)
        try:
            setattr(owner, attribute, value)
        except TypeError:
            if isinstance(value, int) and not isinstance(value, bool) and value < 0:
                raise ValueError(f"{function}(): {name}={value} must be a whole number >= 0") \
                    from None
            raise TypeError(f"{function}(): {name}={value!r} has the wrong type") from None


def termination(iterations, time_limit=0.0, cpu_time_limit=0.0, target=None, stagnation=0):
    """The engine's stop criteria (aco/termination.hpp)."""
    from . import _core
    t = _core.aco.Termination()
    apply(t, {"iterations": "max_iterations", "time_limit": "time_limit_s",
              "cpu_time_limit": "cpu_time_limit_s", "stagnation": "stagnation_iterations"},
          {"iterations": iterations, "time_limit": time_limit,
           "cpu_time_limit": cpu_time_limit, "stagnation": stagnation}, "termination")
    if target is not None:
        t.target_cost = float(target)
    return t
