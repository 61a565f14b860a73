# Seed 000: J. E. Steelman, Frequency Response of α-β-γ Trackers (1978).
# Figures 1-6 (one response table and one figure each); Tables 1-5, the design example, the
# equations' table of agreement and every claim: the study, claims and report rules are
# generated for every document in documents.smk.

S78 = config["steelman1978"]


wildcard_constraints:
    fig="fig[1-6]",


script_rule(
    "steelman_frequency_response",
    "frequency_response.py",
    output={"data": "results/steelman1978/freqresp/{fig}.csv"},
    log="steelman1978/frequency_response_{fig}",
    params={
        "figure": lambda wildcards: S78["figures"][wildcards.fig],
        "grids": S78["grids"],
        "digits": config["significant_digits"],
    },
)


script_rule(
    "steelman_figure",
    "plot_frequency_response.py",
    input={"data": "results/steelman1978/freqresp/{fig}.csv"},
    output={
        "png": report(
            "results/steelman1978/figures/{fig}.png",
            category="Steelman 1978",
            subcategory="Figures",
            labels={"figure": "{fig}"},
        )
    },
    log="steelman1978/figure_{fig}",
    params={
        "axes": lambda wildcards: S78["figures"][wildcards.fig]["axes"],
        "caption": lambda wildcards: S78["figures"][wildcards.fig]["caption"],
        "dpi": config["figure_dpi"],
    },
)
