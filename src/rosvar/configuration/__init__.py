"""Step-by-step configuration: user choices over the feature model, and what they imply.

Data flows one way: the outputs (CLI, web) hand lists of :class:`~.choices.UserChoice` to a
:class:`~.engine.Configurator`, which answers with a :class:`~.engine.ConfigurationState`
computed from the feature model's solver and the variational launch models.
"""
