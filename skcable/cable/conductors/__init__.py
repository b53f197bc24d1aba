"""Overhead line conductors (issue 24): whole lines at array speed, ratings, fatigue, catalogue."""
